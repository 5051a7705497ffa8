// acoustics/bubble/bubble_oscillator.cpp — gathers a bubble's ω₀ (minnaert.h), damping (damping.h) and
// amplitude (excitation.h) into one set of oscillator constants. docs/physics.md §3, §4, §7.3.
#include "acoustics/bubble/bubble_oscillator.h"

#include "acoustics/bubble/damping.h"
#include "acoustics/bubble/excitation.h"
#include "acoustics/bubble/minnaert.h"

namespace fluidsound::acoustics {

OscillatorConstants bubbleOscillator(double radius, double ambientPressure,
                                     const LiquidProperties& liquid, const OscillatorModel& model,
                                     std::optional<double> amplitude) {
  OscillatorConstants constants;
  constants.angularFrequency = naturalAngularFrequency(radius, ambientPressure, liquid, model);
  const double gasPressure0 = gasPressure(radius, ambientPressure, liquid, model);
  const Damping damping = bubbleDamping(radius, constants.angularFrequency, gasPressure0, liquid, model);
  constants.dampingConstant = damping.dampingConstant;
  constants.decayRate = damping.decayRate;
  constants.amplitude =
      amplitude ? *amplitude : excitationAmplitude(radius, constants.angularFrequency, liquid, model);
  return constants;
}

}  // namespace fluidsound::acoustics
