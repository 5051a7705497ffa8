// acoustics/transfer/air_column_rings.cpp — see air_column_rings.h.
#include "acoustics/transfer/air_column_rings.h"

#include <complex>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>

#include "acoustics/bubble/instantaneous_frequency.h"
#include "acoustics/bubble/minnaert.h"
#include "acoustics/transfer/air_pressures.h"
#include "acoustics/transfer/resonator_ring.h"

namespace fluidsound::acoustics {

void addAirColumnRings(BubbleTrackSet& tracks, const FrameSamples& work, const WaterHelmholtz& water,
                       const TransferSetup& setup, const FrameAirFields& air, GeometricTransferStats& stats) {
  // The resonances of the listener whose solve found the strongest: the vessel's own, which
  // every listener's solve drives (a hidden listener's more weakly).
  std::vector<AirResonance> resonances;
  for (const WaveAirField* field : air)
    if (std::vector<AirResonance> r = field->resonances();
        !r.empty() && (resonances.empty() || r.front().gain > resonances.front().gain))
      resonances = std::move(r);
  if (resonances.empty()) return;
  std::vector<std::pair<std::size_t, PointSample>> births;  // bubble, its birth sample's stencil
  for (const auto& [b, s] : work) {
    if (s != 0) continue;
    PointSample stencil = water.sampleAt(samplePosition(tracks, b, s));
    if (!stencil.cells.empty()) births.emplace_back(b, std::move(stencil));
  }
  if (births.empty()) return;
  std::vector<RingingBubble> ringing;
  std::vector<double> bubbleOmega;
  for (const auto& [b, stencil] : births) {
    const BubbleTrack& bubble = tracks.bubbles[b];
    ringing.push_back(ringingBubble(bubble, setup.liquid, setup.model));
    const double pressure = ambientPressureAt(bubble.track.front().depth, setup.liquid, setup.model);
    bubbleOmega.push_back(naturalAngularFrequency(bubble.radius, pressure, setup.liquid, setup.model));
  }
  for (const AirResonance& resonance : resonances) {
    const double omega = 2.0 * std::numbers::pi * resonance.frequency, beta = resonance.decayRate;
    const std::complex<double> pole(-beta, omega);
    const std::unique_ptr<HelmholtzFactor> factor = water.factorise(omega);
    ++stats.factorisations;
    std::vector<ResonatorRing> rings(births.size(), ResonatorRing{resonance.frequency, beta, {}, {}});
    for (std::size_t l = 0; l < setup.listeners.size(); ++l) {
      const Vec3& x = setup.listeners[l].position;
      std::vector<Complex> p = airPressures(water, x, omega, setup.air, air[l]);
      const std::vector<Complex> background = airPressures(water, x, omega, setup.air);
      for (std::size_t a = 0; a < p.size(); ++a) p[a] -= background[a];
      const Eigen::VectorXcd u = factor->solve(water.rightHandSide(p));
      ++stats.solves;
      for (std::size_t i = 0; i < births.size(); ++i) {
        const Complex resonant =
            water.evaluate(births[i].second, u, p) * 4.0 * std::numbers::pi / (omega * setup.liquid.density);
        const Complex amplitude = ringAmplitude(beta * resonant, pole, bubbleOmega[i], ringing[i].deep.decayRate);
        rings[i].gain.push_back(std::abs(amplitude));
        rings[i].phase.push_back(std::arg(amplitude));
      }
    }
    for (std::size_t i = 0; i < births.size(); ++i)
      tracks.bubbles[births[i].first].rings.push_back(std::move(rings[i]));
    stats.rings += births.size();
  }
}

}  // namespace fluidsound::acoustics
