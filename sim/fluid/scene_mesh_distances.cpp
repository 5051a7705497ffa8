// sim/fluid/scene_mesh_distances.cpp — see scene_mesh_distances.h.
#include "sim/fluid/scene_mesh_distances.h"

#include <stdexcept>
#include <string>

#include "sim/fluid/mesh_distance.h"
#include "sim/fluid/region_free_surface.h"
#include "sim/fluid/solid_geometry.h"

namespace fluidsound::sim {
namespace {
/// The node distance of `shape` on `grid` when it is a mesh; an empty entry otherwise.
MeshNodeDistance nodeDistanceOf(const Shape& shape, const GridGeometry& grid) {
  MeshNodeDistance out;
  const auto* mesh = std::get_if<MeshFile>(&shape);
  if (mesh == nullptr) return out;
  if (!mesh->surface)
    throw std::invalid_argument(mesh->file.string() +
                                ": the mesh's triangles were not read (io::loadSceneMeshes)");
  out.grid = grid;
  out.nodes = meshNodeDistance(*mesh->surface, MeshPlacement{}, grid);
  return out;
}
}  // namespace

SceneMeshDistances sceneMeshDistances(const FluidScene& scene, const GridGeometry& grid) {
  SceneMeshDistances out;
  bool anyRegionMesh = false;
  for (const LiquidRegion& region : scene.liquid) {
    out.liquid.push_back(nodeDistanceOf(region.shape, grid));
    anyRegionMesh = anyRegionMesh || std::holds_alternative<MeshFile>(region.shape);
  }
  for (const Solid& solid : scene.solids) out.solids.push_back(nodeDistanceOf(solid.shape, grid));
  if (!anyRegionMesh) return out;
  // Where each mesh region's surface is free, against the solids where they start.
  const Array3f solidNodes = solidNodeDistance(grid, scene.domain, scene.solids, 0.0, out.solids);
  for (std::size_t i = 0; i < scene.liquid.size(); ++i)
    if (const auto* mesh = std::get_if<MeshFile>(&scene.liquid[i].shape))
      out.liquid[i].freeSurfaceAtCentres =
          regionFreeSurfaceAtCentres(*mesh->surface, solidNodes, grid);
  return out;
}

const MeshNodeDistance* meshEntry(const Shape& shape, std::span<const MeshNodeDistance> meshes,
                                  std::size_t index) {
  const auto* mesh = std::get_if<MeshFile>(&shape);
  if (mesh == nullptr) return nullptr;
  if (index >= meshes.size() || meshes[index].nodes.elementCount() == 0)
    throw std::invalid_argument(
        mesh->file.string() +
        ": the mesh's distance was not computed on the grid (sim::sceneMeshDistances)");
  return &meshes[index];
}

}  // namespace fluidsound::sim
