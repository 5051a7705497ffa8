// acoustics/modal/stick_slip.h — friction sound from stick–slip, after the friction paper (shared
// solids.md §1.3): the sliding contact's real contact points bond and break; each break releases
// the friction the bond held as an impulse along the sliding direction, which rings the body's
// modes (docs/solids.md, Friction). The paper's patch of size a with 1/a = α·v gives a break
// every a/v = a₁/v² seconds (a₁ the patch at 1 m/s): the squeal's rate rises with the square of
// the speed. Used as the paper's own caveats advise (solids.md §1.3): a stylised texture
// generator, not a calibrated model.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "acoustics/modal/modal_synthesis.h"
#include "acoustics/modal/surface_roughness.h"

namespace fluidsound::acoustics {

struct StickSlipSettings {
  double patchAtUnitSpeed = 3e-3;  ///< a₁ [m]: the patch at 1 m/s (the paper's metal sample: 3 mm)
  /// Relative spread of each patch's size (0: the paper's smooth metal, a pitched squeal;
  /// 0.3: a rough surface, no pitch) [-]
  double patchSpread = 0.0;
  double minimumSpeed = 1e-3;      ///< below it the contact sticks: no breaks [m/s]
  /// How long a slip lasts, as a share of its patch's time a/v: each slip is a half-sine force
  /// pulse of that duration, not an ideal impulse (a choice; the paper gives none). An ideal
  /// impulse rang every mode up to 20 kHz at full strength: the sliding box's slips, each a
  /// sixth of its landing's impulse, sounded 500× louder than the landing, whose Hertz contact
  /// (0.5 ms) passes little above 1 kHz. [-], ≥ 0; 0: ideal impulses
  double slipShare = 0.1;
  double substep = 1e-3;           ///< the contact log's substep [s]
  std::uint64_t seed = 1;          ///< the patches' sizes (deterministic)
};

/// @brief The slips of one sliding contact over its substeps (consecutive, in time order): a slip
///        each time the contact has slid a patch a = a₁/v, v the speed now (so every a₁/v²
///        seconds at steady speed), releasing the friction force's impulse since the last slip,
///        at most the friction over one patch at the speed now (F·a/v: a contact speeding up from
///        rest does not release its whole slow start at once), along it, at the substep's node;
///        lasting slipShare·a/v; none in rolling substeps or below minimumSpeed. At steady speed the slips' impulses sum
///        to the friction's over the sliding substeps, up to the last partial patch.
std::vector<ModalImpact> stickSlipImpacts(std::span<const RubbingSample> substeps, const StickSlipSettings& settings);

}  // namespace fluidsound::acoustics
