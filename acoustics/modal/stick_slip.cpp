// acoustics/modal/stick_slip.cpp — see stick_slip.h.
#include "acoustics/modal/stick_slip.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace fluidsound::acoustics {

std::vector<ModalImpact> stickSlipImpacts(std::span<const RubbingSample> substeps, const StickSlipSettings& settings) {
  if (!(settings.patchAtUnitSpeed > 0.0) || !(settings.patchSpread >= 0.0) || !(settings.minimumSpeed > 0.0) ||
      !(settings.substep > 0.0) || !(settings.slipShare >= 0.0))
    throw std::invalid_argument(
        "stickSlipImpacts: patch and substep > 0, spread and slip share >= 0, minimum speed > 0");
  std::mt19937_64 random(settings.seed);
  std::normal_distribution<double> spread(0.0, 1.0);
  // Each patch's size relative to the paper's a₁/v (its random spread), drawn when it forms.
  const auto nextFactor = [&] { return std::max(1.0 + settings.patchSpread * spread(random), 0.05); };
  std::vector<ModalImpact> slips;
  double slid = 0.0, factor = 0.0;                    // along the current patch [m]; 0: none
  Eigen::Vector3d held = Eigen::Vector3d::Zero();     // friction impulse held by the bond [N·s]
  for (const RubbingSample& s : substeps) {
    const double start = s.time - settings.substep;
    if (s.rolling || s.speed < settings.minimumSpeed) {  // sticking or rolling: the bond re-forms
      slid = 0.0, factor = 0.0, held.setZero();
      continue;
    }
    if (factor == 0.0) factor = nextFactor();
    // The patch at this substep's speed (a contact speeding up from rest breaks at a₁/v of its
    // speed now, not of the crawl it started at), and the most a bond of it holds: the friction
    // over one patch at this speed, F·a/v. Without that bound a contact starting from rest
    // released in one slip the friction of its whole slow start (0.05 N·s for the box of
    // scenes/sliding_box, 70× a steady slip, louder than its landing).
    // Within the substep: slide at its speed, breaking at each patch's end.
    double t = 0.0;
    while (t < settings.substep) {
      const double patch = factor * settings.patchAtUnitSpeed / s.speed;
      const double bond = s.friction.norm() * patch / s.speed;
      const double toBreak = std::max(patch - slid, 0.0) / s.speed;
      const double step = std::min(toBreak, settings.substep - t);
      held += s.friction * step;
      if (held.norm() > bond) held *= bond / held.norm();
      slid += s.speed * step;
      t += step;
      if (slid >= patch * (1.0 - 1e-12)) {
        slips.push_back({start + t, s.surfaceNode, held, settings.slipShare * patch / s.speed});
        held.setZero();
        slid = 0.0;
        factor = nextFactor();
      }
    }
  }
  return slips;
}

}  // namespace fluidsound::acoustics
