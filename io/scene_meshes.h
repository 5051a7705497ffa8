// io/scene_meshes.h — loading the meshes a scene names (`liquid[i].mesh`, `solids[i].mesh`) into
// the scene: each becomes a signed distance at the solver grid's nodes that the simulation reads.
#pragma once

#include "sim/scene.h"

namespace fluidsound::io {

/// @brief For every mesh liquid region and mesh solid of `scene`: reads the file
///        (io/mesh_file.h), places it (solids: scale about the origin, rotate about the centre of
///        the scaled bounding box, translate — docs/scene.md; liquid regions as written), requires
///        it closed and fills MeshFile::distance with its signed distance at the nodes of
///        scene.grid() (io/mesh_distance.h) and, for a solid, MeshFile::surface with its placed
///        triangles (for the ray queries of sim/fluid/solid_mesh_rays.h). A kinematic mesh solid's
///        path then shifts both (sim/fluid/solid_geometry.h, sim/fluid/solid_mesh_rays.h).
/// @throws InputError naming the scene file and the field (`solids[2].mesh`) for a missing,
///         malformed or open mesh
void loadSceneMeshes(sim::Scene& scene);

}  // namespace fluidsound::io
