// io/scene_meshes.h — reading the meshes a scene names (`liquid[i].mesh`, `solids[i].mesh`) into
// the scene record: each becomes its placed triangles (the solver computes its distances from
// them on its own grid, sim/fluid/scene_mesh_distances.h, so the cell size may change later).
#pragma once

#include "sim/scene.h"

namespace fluidsound::io {

/// @brief For every mesh liquid region and mesh solid of `scene`: reads the file
///        (io/mesh_file.h), places it (solids: scale about the origin, rotate about the centre of
///        the scaled bounding box, translate — docs/scene.md; liquid regions as written), requires
///        it closed and keeps the placed triangles in MeshFile::surface. A kinematic mesh solid's
///        path then shifts them in the solver (sim/fluid/solid_geometry.h,
///        sim/fluid/solid_mesh_rays.h).
/// @throws InputError naming the scene file and the field (`solids[2].mesh`) for a missing,
///         malformed or open mesh
void loadSceneMeshes(sim::Scene& scene);

}  // namespace fluidsound::io
