// sim/fluid/velocity_extrapolation.h — extending face velocities from where the projection made them
// valid (next to liquid) into air and solids, layer by layer, so that particles and advection can
// read any face (Bridson 2015, §4.4; Batty's Fluid3D "extrapolate").
#pragma once

#include <array>
#include <cstdint>

#include "sim/fluid/array3.h"
#include "sim/fluid/mac_velocity.h"

namespace fluidsound::sim {

using FaceMask = std::array<Array3<std::uint8_t>, 3>;

/// @brief For `layers` rounds, each invalid face with valid 6-neighbours (same component) takes
///        their mean and becomes valid. Each round reads only the previous round's values, so
///        the result does not depend on the order or the threads.
void extrapolateVelocity(MacVelocity& velocity, FaceMask valid, int layers);

}  // namespace fluidsound::sim
