// sim/fluid/particle_advection.h — moving particles through the grid velocity (second-order
// Runge–Kutta), keeping them out of solids and deleting those that leave through open faces.
#pragma once

#include "sim/fluid/array3.h"
#include "sim/fluid/fluid_scene.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particles.h"
#include "sim/fluid/solid_boundary.h"

namespace fluidsound::sim {

/// How far short of a mesh surface a stopped particle is left, in cells: far above the float
/// rounding of positions (≈ 1e-7 of the coordinates), far below anything the grid resolves.
inline constexpr double kMeshWallOffsetCells = 1e-3;

/// @brief x ← x + Δt·u(x + ½Δt·u(x)) (midpoint rule), then:
///        - a particle whose straight move x → x' crosses a mesh solid's surface (a ray query,
///          the solid's own motion included) stops kMeshWallOffsetCells short of it on its own
///          side, loses the velocity component into the wall (relative to the wall's) and its
///          APIC affine part (it moves on, if at all, with the velocity alone, as under PIC);
///        - one beyond an open domain face is deleted; the others are clamped inside;
///        - one that ends inside a solid by the nodal distance (< 0) is pushed back along the
///          distance gradient to kSolidMargin cells outside and loses its velocity into the
///          solid, unless that push would cross a mesh surface (a thin wall the grid does not
///          resolve: the ray test is the truth).
/// @return particles deleted at open faces
/// @param solids  the solids (their grid is the velocity's) at times.to; the mesh solids move
///                from times.from to times.to during the step
std::size_t advectParticles(Particles& particles, const MacVelocity& velocity,
                            const SolidBoundary& solids, const SolidTimes& times, double dt);

}  // namespace fluidsound::sim
