// sim/particle_advection.h — moving particles through the grid velocity (second-order
// Runge–Kutta), keeping them out of solids and deleting those that leave through open faces.
#pragma once

#include "sim/array3.h"
#include "sim/grid.h"
#include "sim/mac_velocity.h"
#include "sim/particles.h"
#include "sim/scene.h"

namespace fluidsound::sim {

/// @brief x ← x + Δt·u(x + ½Δt·u(x)) (midpoint rule). A particle that ends inside a solid
///        (node distance < 0) is pushed back along the distance gradient to kSolidMargin cells
///        outside; one beyond an open domain face is deleted; the others are clamped inside.
/// @return particles deleted at open faces
std::size_t advectParticles(Particles& particles, const MacVelocity& velocity, const GridGeometry& grid,
                            const Array3f& solidNodeDistance, const Domain& domain, double dt);

}  // namespace fluidsound::sim
