// sim/fluid/mesh_distance.h — pressure projection input for mesh solids: the signed distance from
// the solver grid's nodes to a closed triangle mesh placed in the scene (scale, then translate), in
// the layout of solidNodeDistance, computed with OpenVDB's mesh-to-volume conversion.
#pragma once

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/triangle_mesh.h"

namespace fluidsound::sim {

/// Where a mesh goes: p_world = scale · p_file + translate (docs/scene.md, "Placement of a
/// solid", without the rotation).
struct MeshPlacement {
  double scale = 1.0;  ///< [-], > 0, about the world origin (Solid::scale)
  /// [m]: Solid::translate, plus the path translation for a kinematic solid
  Vec3 translate{};
};

struct MeshDistanceSettings {
  /// Half width of the band of computed distances [cells]; values are clamped to ±halfWidth·h.
  /// The corners of a cell that the surface cuts are at most √3 h ≈ 1.73 h from it, so 2 is
  /// the least that gives the face-area weights their input; 3 is OpenVDB's level-set default
  /// (LEVEL_SET_HALF_WIDTH).
  int halfWidthCells = 3;
};

/// @brief Signed distance [m] from each grid node (origin + (i, j, k)·h, i = 0 … ni) to the
///        surface of `mesh` placed by `placement`, negative inside, clamped to ±halfWidthCells·h.
///        Computed with OpenVDB's meshToVolume on a grid whose voxel centres are the nodes
///        (voxel size h, no interpolation), one cell wider than kept, and without its
///        renormalisation pass (which, measured, moved exact values 1.5–2 h from a thin slab by
///        up to 0.07 h). Three zones:
///        - |d| ≤ √11/2 h ≈ 1.66 h (≈ 1.87 h beside flat parts of the surface): the exact
///          closest-triangle distance (float). This holds every corner of a cut cell except
///          where the nearest feature is a vertex or an edge in an unlucky direction (the last
///          0.07 h up to √3 h);
///        - farther, up to the band: OpenVDB's band expansion, the distance to a nearby triangle,
///          so never less than the true |d| and the sign right (measured up to 0.46 h more
///          outside an icosphere of radius 10 h, 0.86 h more beside the rim of a slab);
///        - beyond the band: exactly ±halfWidthCells·h.
///        Inside/outside comes from OpenVDB's flood fill of the intersected voxels, which does
///        not depend on the triangles' orientation.
/// @param mesh       a closed mesh (io/mesh_closedness.h); the sign of an open one is
/// unreliable
/// @param placement  scale > 0 and translation
/// @param grid       the solver grid; only its nodes are computed, the mesh may extend beyond
/// @param settings   halfWidthCells ≥ 2
/// @return Array3f of size grid.nodeCount() [m]; all +halfWidthCells·h for a mesh without triangles
/// @throws std::invalid_argument for scale ≤ 0 or not finite, or halfWidthCells < 2
/// @note Thin features. The values are distances at the nodes, so a wall thinner than a cell is
///       seen only where a node lies inside it: a 2 mm wall in 5 mm cells gives negative nodes
///       (and closed faces) when it holds a plane of nodes, and otherwise only positive values,
///       down to the gap between the wall and the nearest node plane, with every face through
///       the wall open: it leaks (measured in tests/sim/fluid/mesh_distance_test.cpp,
///       MeshDistance.ThinWallIsSeenOnlyWhenItHoldsANodePlane). A finer OpenVDB grid would not
///       help: it is the sampling at the nodes that misses the wall. Closing such walls is the
///       thin-obstacle task (ray queries).
/// @note Rotation (Solid::rotateDegrees) is not applied yet.
Array3f meshNodeDistance(const TriangleMesh& mesh, const MeshPlacement& placement,
                         const GridGeometry& grid, const MeshDistanceSettings& settings = {});

/// @brief Unsigned distance [m] from each grid node to the triangles of `mesh` placed by
///        `placement` — any set of triangles, closed or not — clamped to halfWidthCells·h. The
///        same exact closest-triangle zone and band as meshNodeDistance, without a sign.
/// @throws std::invalid_argument as meshNodeDistance
Array3f meshNodeUnsignedDistance(const TriangleMesh& mesh, const MeshPlacement& placement,
                                 const GridGeometry& grid,
                                 const MeshDistanceSettings& settings = {});

}  // namespace fluidsound::sim
