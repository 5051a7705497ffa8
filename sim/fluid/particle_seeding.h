// sim/fluid/particle_seeding.h — filling the scene's initial liquid regions with jittered particles.
#pragma once

#include <cstdint>
#include <span>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/particles.h"
#include "sim/fluid/fluid_scene.h"

namespace fluidsound::sim {

/// @brief Seeds `perCell` particles (per axis ∛perCell when a cube, else stratified-random) in
///        every cell, at jittered positions (a cube: jittered within the middle half of each
///        sub-cell), keeping those inside a liquid region and outside
///        solids (solid distance interpolated from the nodes > 0). Velocity = the region's.
///        The jitter comes from `seed` and the cell index, so the result does not depend on threads.
/// @param solidNodeDistance  signed distance to solids at the grid nodes [m] (negative inside)
/// @throws std::invalid_argument for a mesh region whose distance was not loaded
Particles seedLiquid(const GridGeometry& grid, std::span<const LiquidRegion> regions,
                     const Array3f& solidNodeDistance, int perCell, std::uint64_t seed);

/// @brief Signed distance to a liquid region's shape [m], negative inside.
/// @throws std::invalid_argument for a mesh region whose distance was not loaded
double regionDistance(const LiquidRegion& region, const Vec3& p);

/// @brief Signed distance [m] to a loaded mesh at p, interpolated from its node samples (exact
///        near the surface, clamped to its band farther away; io/mesh_distance.h).
/// @throws std::invalid_argument if the mesh's distance was not loaded (io::loadSceneMeshes)
double meshDistance(const MeshFile& mesh, const Vec3& p);

/// @brief Trilinear interpolation of a node-sampled field at world position p (clamped to the
///        grid; a NaN coordinate gives NaN, never a read outside the array).
float interpolateNodes(const Array3f& nodes, const GridGeometry& grid, const Vec3& p);

}  // namespace fluidsound::sim
