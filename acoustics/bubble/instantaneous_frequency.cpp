// acoustics/bubble/instantaneous_frequency.cpp — see instantaneous_frequency.h; docs/synthesis.md.
#include "acoustics/bubble/instantaneous_frequency.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "acoustics/bubble/depth_shift.h"
#include "acoustics/bubble/minnaert.h"

namespace fluidsound::acoustics {

RingingBubble ringingBubble(const BubbleTrack& bubble, const LiquidProperties& liquid,
                            const OscillatorModel& model) {
  const double p0 = liquid.ambientPressure;
  OscillatorModel adiabatic = model;
  adiabatic.polytropic = PolytropicModel::Adiabatic;
  return {bubble.radius, bubble.birth,
          bubbleOscillator(bubble.radius, p0, liquid, model, bubble.amplitude),
          naturalAngularFrequency(bubble.radius, p0, liquid, adiabatic)};
}

double instantaneousAngularFrequency(const RingingBubble& bubble, double depth, double time,
                                     const LiquidProperties& liquid, const OscillatorModel& model) {
  const double radius = bubble.radius;
  double w2 = bubble.deep.angularFrequency * bubble.deep.angularFrequency;  // ω² [rad²/s²]
  if (std::isfinite(depth)) {
    w2 *= freeSurfaceFrequencyRatioSquared(radius, depth);  // Strasberg 1953, docs/physics.md §5
    if (model.hydrostatic) {
      // p₀ → p₀ + ρgh acts on the restoring term; applied as the adiabatic model's ratio.
      OscillatorModel adiabatic = model;
      adiabatic.polytropic = PolytropicModel::Adiabatic;
      const double p = ambientPressureAt(depth, liquid, model);
      const double ratio =
          naturalAngularFrequency(radius, p, liquid, adiabatic) / bubble.adiabaticAngularFrequency;
      w2 *= ratio * ratio;
    }
  }
  if (model.chirp) {  // van den Doel 2005: f(t) = f₀(1 + ξβt), docs/physics.md §7.4
    const double rise = 1.0 + model.chirpRiseFactor * bubble.deep.decayRate * (time - bubble.birth);
    w2 *= rise * rise;
  }
  // The free response of v̈ + 2βv̇ + ω₀²v = 0 rings at ω_d = √(ω₀² − β²) (docs/physics.md §1).
  const double beta = bubble.deep.decayRate;
  return std::sqrt(std::max(w2 - beta * beta, 0.0));
}

double peakAngularFrequency(const RingingBubble& ringing, const BubbleTrack& bubble,
                            double cutoffDecibels, const LiquidProperties& liquid,
                            const OscillatorModel& model) {
  double w = instantaneousAngularFrequency(ringing, std::numeric_limits<double>::infinity(),
                                           bubble.birth, liquid, model);
  for (const TrackSample& k : bubble.track)
    w = std::max(w, instantaneousAngularFrequency(ringing, k.depth, bubble.birth, liquid, model));
  // The chirp's rise at the cut-off: ξβ·t_cut = ξ ln(10^(dB/20)) (physics.md §7.4).
  if (model.chirp)
    w *= 1.0 + model.chirpRiseFactor * std::log(std::pow(10.0, cutoffDecibels / 20.0));
  return w;
}

}  // namespace fluidsound::acoustics
