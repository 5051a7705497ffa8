// sim/fluid/particle_seeding.h — filling the scene's initial liquid regions with jittered particles.
#pragma once

#include <cstdint>
#include <span>

#include "sim/fluid/array3.h"
#include "sim/fluid/fluid_scene.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/particles.h"
#include "sim/fluid/scene_mesh_distances.h"

namespace fluidsound::sim {

/// @brief Seeds `perCell` particles (per axis ∛perCell when a cube, else stratified-random) in
///        every cell, at jittered positions (a cube: jittered within the middle half of each
///        sub-cell), keeping those inside a liquid region and outside
///        solids (solid distance interpolated from the nodes > 0). Velocity = the region's.
///        The jitter comes from `seed` and the cell index, so the result does not depend on
///        threads.
/// @param solidNodeDistance  signed distance to solids at the grid nodes [m] (negative inside)
/// @param regionMeshes       the mesh regions' node distances, one entry per region
///                           (SceneMeshDistances::liquid); may be empty when no region is a mesh
/// @throws std::invalid_argument for a mesh region whose distance regionMeshes does not hold
Particles seedLiquid(const GridGeometry& grid, std::span<const LiquidRegion> regions,
                     const Array3f& solidNodeDistance, int perCell, std::uint64_t seed,
                     std::span<const MeshNodeDistance> regionMeshes = {});

/// @brief Signed distance to a liquid region's shape [m], negative inside.
/// @param mesh  the region's node distance when it is a mesh (meshEntry), else unused
/// @throws std::invalid_argument for a mesh region without `mesh`
double regionDistance(const LiquidRegion& region, const Vec3& p,
                      const MeshNodeDistance* mesh = nullptr);

/// @brief Signed distance [m] to a mesh at p, interpolated from its node samples (exact near the
///        surface, clamped to its band farther away; sim/fluid/mesh_distance.h).
double meshDistance(const MeshNodeDistance& mesh, const Vec3& p);

/// @brief Trilinear interpolation of a node-sampled field at world position p (clamped to the
///        grid; a NaN coordinate gives NaN, never a read outside the array).
float interpolateNodes(const Array3f& nodes, const GridGeometry& grid, const Vec3& p);

}  // namespace fluidsound::sim
