// acoustics/modal/body_contact_points.h — one body's side of the rigid-body stage's contact log
// (sim/core/contact_record.h) in the body's own frame, where its modes are: the impulse on it and
// the normal into it turned by the inverse of its rotation in that substep, the point in its
// frame, and where the body was (for its radiation). docs/solids.md, "Bodies in run".
#pragma once

#include <vector>

#include "acoustics/modal/contact_impacts.h"
#include "sim/core/contact_record.h"

namespace fluidsound::acoustics {

/// @brief The points of `log` that touch `body` (an index into log.bodies), from its side, in time
///        order. The rolling speed over its surface is the rolling rate times the radius of the
///        body that rolls at the point (its local point's distance from its reference): the other
///        body's when that one moves, else this one's.
/// @throws std::invalid_argument if `body` is not one of the log's bodies
std::vector<BodyContactPoint> bodyContactPoints(const sim::ContactLog& log, int body);

}  // namespace fluidsound::acoustics
