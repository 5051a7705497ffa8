// acoustics/modal/stick_slip.cpp — see stick_slip.h.
#include "acoustics/modal/stick_slip.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace fluidsound::acoustics {

std::vector<ModalImpact> stickSlipImpacts(std::span<const RubbingSample> substeps, const StickSlipSettings& settings) {
  if (!(settings.patchAtUnitSpeed > 0.0) || !(settings.patchSpread >= 0.0) || !(settings.minimumSpeed > 0.0) ||
      !(settings.substep > 0.0))
    throw std::invalid_argument("stickSlipImpacts: patch and substep > 0, spread >= 0, minimum speed > 0");
  std::mt19937_64 random(settings.seed);
  std::normal_distribution<double> spread(0.0, 1.0);
  const auto nextPatch = [&](double speed) {
    const double a = settings.patchAtUnitSpeed / speed * (1.0 + settings.patchSpread * spread(random));
    return std::max(a, 0.05 * settings.patchAtUnitSpeed / speed);  // a spread never makes a patch vanish
  };
  std::vector<ModalImpact> slips;
  double slid = 0.0, patch = 0.0;                     // along the current patch [m]
  Eigen::Vector3d held = Eigen::Vector3d::Zero();     // friction impulse held by the bond [N·s]
  for (const RubbingSample& s : substeps) {
    const double start = s.time - settings.substep;
    if (s.rolling || s.speed < settings.minimumSpeed) {  // sticking or rolling: the bond re-forms
      slid = 0.0, patch = 0.0, held.setZero();
      continue;
    }
    if (patch == 0.0) patch = nextPatch(s.speed);
    // Within the substep: slide at its speed, breaking at each patch's end.
    double t = 0.0;
    while (t < settings.substep) {
      const double toBreak = (patch - slid) / s.speed;
      const double step = std::min(toBreak, settings.substep - t);
      held += s.friction * step;
      slid += s.speed * step;
      t += step;
      if (slid >= patch * (1.0 - 1e-12)) {
        slips.push_back({start + t, s.surfaceNode, held, 0.0});
        held.setZero();
        slid = 0.0;
        patch = nextPatch(s.speed);
      }
    }
  }
  return slips;
}

}  // namespace fluidsound::acoustics
