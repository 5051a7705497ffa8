// sim/fluid/region_free_surface.cpp — see region_free_surface.h.
#include "sim/fluid/region_free_surface.h"

#include <algorithm>

#include "sim/fluid/liquid_level_set.h"
#include "sim/fluid/mesh_distance.h"
#include "sim/fluid/particle_seeding.h"

namespace fluidsound::sim {

Array3f regionFreeSurfaceAtCentres(const TriangleMesh& region, const Array3f& solidNodes,
                                   const GridGeometry& grid) {
  const double contact = kSolidContactCells * grid.cellSize;
  // On (or beyond) the grid's boundary — a closed wall, or an open face the liquid runs on
  // through — or against a solid.
  const auto againstWallOrSolid = [&](const Vec3& p) {
    for (int a = 0; a < 3; ++a)
      if (p[a] <= grid.origin[a] + contact ||
          p[a] >= grid.origin[a] + grid.cells[a] * grid.cellSize - contact)
        return true;
    return interpolateNodes(solidNodes, grid, p) <= contact;
  };
  TriangleMesh free;
  free.vertices = region.vertices;
  for (const auto& t : region.triangles) {
    Vec3 corner[3], centroid{0.0, 0.0, 0.0};
    for (int v = 0; v < 3; ++v)
      for (int a = 0; a < 3; ++a) {
        corner[v][a] = region.vertices[t[v]][a];
        centroid[a] += corner[v][a] / 3.0;
      }
    if (!(againstWallOrSolid(corner[0]) && againstWallOrSolid(corner[1]) &&
          againstWallOrSolid(corner[2]) && againstWallOrSolid(centroid)))
      free.triangles.push_back(t);
  }
  // A grid whose nodes are the cell centres: the samples are taken there, not interpolated.
  GridGeometry centres = grid;
  for (int a = 0; a < 3; ++a) {
    centres.origin[a] += 0.5 * grid.cellSize;
    centres.cells[a] -= 1;
  }
  const Array3f whole = meshNodeDistance(region, MeshPlacement{}, centres);
  const Array3f toFree = meshNodeUnsignedDistance(free, MeshPlacement{}, centres);
  Array3f out = whole;
  auto& value = out.values();
  const auto& freeValue = toFree.values();
  for (std::size_t c = 0; c < value.size(); ++c)
    if (value[c] < 0.0f) value[c] = -freeValue[c];
  return out;
}

}  // namespace fluidsound::sim
