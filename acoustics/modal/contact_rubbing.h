// acoustics/modal/contact_rubbing.h — the rolling and sliding contacts in a body's contact log as
// the substeps of rubbing forces (surface_roughness.h): each touch of one other body over
// consecutive substeps, its load, its speed over the surface and where it touches (docs/solids.md,
// Rolling and sliding).
#pragma once

#include <span>
#include <vector>

#include "acoustics/modal/contact_impacts.h"
#include "acoustics/modal/surface_roughness.h"

namespace fluidsound::acoustics {

/// One touch of another body, substep by substep.
struct RubbingContact {
  int other = 0;                         ///< the body or wall touched (the log's index)
  std::vector<RubbingSample> substeps;   ///< consecutive substeps
};

/// @brief The touches in a body's contact points (in time order), one per other body and run of
///        consecutive substeps in which they touch. Each substep: the normal force Σ J_n / Δt, the
///        friction force (the impulses' tangential part / Δt), the
///        impulse-weighted speed over the surface (sliding plus rolling speed), the normal, the
///        surface node nearest the impulse-weighted point; rolling when its rolling speed exceeds
///        its sliding speed.
std::vector<RubbingContact> rubbingFromContacts(std::span<const BodyContactPoint> points, const ModalModel& model,
                                                double substep);

}  // namespace fluidsound::acoustics
