// sim/fluid/solid_rotation.h — what a solid's `rotate` field means (sim::Solid::rotateDegrees;
// docs/scene.md, "Placement of a solid"): Euler angles in degrees about the fixed x, then y, then
// z axes. Part of the scene record's definition: io places mesh solids by it when it reads them,
// the solver places boxes by it.
#pragma once

#include <array>

#include "sim/core/vec3.h"

namespace fluidsound::sim {

using Mat3 = std::array<Vec3, 3>;  ///< rows

/// @return the world-from-local rotation R = Rz·Ry·Rx for Euler angles [degrees]
Mat3 rotationFromEulerDegrees(const Vec3& degrees);

/// @brief `offset` turned by Euler angles [degrees] about x, then y, then z (fixed world axes):
///        R·offset with R = Rz·Ry·Rx, as a solid's `rotate` turns its shape about its centre
///        (docs/scene.md, "Placement of a solid").
Vec3 rotateByEulerDegrees(const Vec3& offset, const Vec3& degrees);

}  // namespace fluidsound::sim
