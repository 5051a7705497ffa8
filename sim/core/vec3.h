// sim/core/vec3.h — the one point or direction type of every stage: world space [m] (or a unit
// vector, or a velocity [m/s], as the name at its use says), x, y, z.
#pragma once

#include <array>

namespace fluidsound {

using Vec3 = std::array<double, 3>;

}  // namespace fluidsound
