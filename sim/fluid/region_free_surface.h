// sim/fluid/region_free_surface.h — the liquid level set's start for a mesh liquid region: where
// its surface is free. Water modelled up to a glass's or a basin's walls has faces lying on those
// walls; they are where the liquid meets the solid, not a surface, and the liquid level set must
// not start with one there (sim/fluid/liquid_level_set.h).
#pragma once

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/triangle_mesh.h"

namespace fluidsound::sim {

/// @brief Signed distance [m] at the solver grid's cell centres to the free part of a closed
///        liquid-region mesh (placed, world coordinates): its triangles that do not lie against
///        a solid or on the grid's boundary — a triangle does when each of its three corners and
///        its centroid has a solid distance (`solidNodes` interpolated) of at most
///        kSolidContactCells·h or lies that close to the boundary (a closed wall, or an open
///        face the liquid runs on through). Inside the region: minus the distance to the nearest
///        free triangle (exact near it, sim/fluid/mesh_distance.h), −3h beyond the band or when no
///        triangle is free; outside: the distance to the whole mesh. Sampled at the centres
///        themselves, not interpolated from nodes, which reads a convex edge up to ½h shallow.
/// @param solidNodes  the solids' signed distance at the grid nodes, closed domain walls
///                    included (solidNodeDistance at the start time) [m]
/// @return size grid.cells
Array3f regionFreeSurfaceAtCentres(const TriangleMesh& region, const Array3f& solidNodes,
                                   const GridGeometry& grid);

}  // namespace fluidsound::sim
