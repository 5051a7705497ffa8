// sim/fluid/scene_mesh_distances.h — the signed distances the solver reads for a scene's mesh
// solids and mesh liquid regions, computed from their placed triangles (MeshFile::surface) on
// the solver's own grid when it is built; the scene record holds the triangles only.
#pragma once

#include <span>
#include <vector>

#include "sim/fluid/array3.h"
#include "sim/fluid/fluid_scene.h"
#include "sim/fluid/grid.h"

namespace fluidsound::sim {

/// A mesh's signed distance sampled at the nodes of a grid [m], negative inside, clamped to a
/// band of a few cells (sim/fluid/mesh_distance.h); interpolated by meshDistance
/// (sim/fluid/particle_seeding.h).
struct MeshNodeDistance {
  GridGeometry grid;  ///< the nodes are origin + (i, j, k)·cellSize
  Array3f nodes;      ///< size grid.nodeCount(); empty for a box or a sphere
  /// For a liquid region: the signed distance at the cell centres (size grid.cells) to its free
  /// surface, its faces not lying against a solid (sim/fluid/region_free_surface.h); empty for
  /// a solid.
  Array3f freeSurfaceAtCentres;
};

/// One entry per scene solid and per liquid region, in the scene's order; a box or a sphere has
/// an empty entry (its distance is exact, computed where it is read).
struct SceneMeshDistances {
  std::vector<MeshNodeDistance> solids;
  std::vector<MeshNodeDistance> liquid;
};

/// @brief The node distance of every mesh solid and mesh liquid region of `scene` on `grid`
///        (meshNodeDistance of MeshFile::surface, placed already), then each mesh region's free
///        surface against the solids where they start (t = 0, closed domain walls included).
/// @throws std::invalid_argument for a MeshFile whose triangles were not read (io::loadSceneMeshes)
SceneMeshDistances sceneMeshDistances(const FluidScene& scene, const GridGeometry& grid);

/// @brief The entry of `meshes` for shape `index` when it is a mesh, checked: nullptr for a box or
///        a sphere.
/// @throws std::invalid_argument for a mesh whose distance `meshes` does not hold
const MeshNodeDistance* meshEntry(const Shape& shape, std::span<const MeshNodeDistance> meshes,
                                  std::size_t index);

}  // namespace fluidsound::sim
