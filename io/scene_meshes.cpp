// io/scene_meshes.cpp — see scene_meshes.h.
#include "io/scene_meshes.h"

#include <memory>
#include <string>

#include "io/input_error.h"
#include "io/mesh_distance.h"
#include "io/mesh_file.h"

namespace fluidsound::io {
namespace {
/// The mesh with p_world = scale · p_file + translate applied to its vertices (in double, then
/// stored as float like the file's own coordinates).
std::shared_ptr<const sim::TriangleMesh> placedMesh(const sim::TriangleMesh& mesh, const MeshPlacement& placement) {
  auto placed = std::make_shared<sim::TriangleMesh>(mesh);
  for (auto& vertex : placed->vertices)
    for (int a = 0; a < 3; ++a)
      vertex[a] = static_cast<float>(placement.scale * vertex[a] + placement.translate[a]);
  return placed;
}

/// Reads and checks the mesh `file` names and fills its distance at the scene grid's nodes and,
/// for a solid (`withSurface`), its placed triangles.
void loadMesh(sim::MeshFile& file, const MeshPlacement& placement, const sim::Scene& scene,
              const std::string& jsonPath, bool withSurface) {
  const MeshReference reference{scene.file.string(), jsonPath};
  const sim::TriangleMesh mesh = readMeshFile(file.file, reference);
  requireClosedMesh(mesh, file.file, reference);
  auto distance = std::make_shared<sim::MeshNodeDistance>();
  distance->grid = scene.grid();
  distance->nodes = meshNodeDistance(mesh, placement, distance->grid);
  file.distance = std::move(distance);
  if (withSurface) file.surface = placedMesh(mesh, placement);
}
}  // namespace

void loadSceneMeshes(sim::Scene& scene) {
  for (std::size_t i = 0; i < scene.liquid.size(); ++i)
    if (auto* mesh = std::get_if<sim::MeshFile>(&scene.liquid[i].shape))
      loadMesh(*mesh, {}, scene, "liquid[" + std::to_string(i) + "].mesh", false);
  for (std::size_t i = 0; i < scene.solids.size(); ++i) {
    sim::Solid& solid = scene.solids[i];
    auto* mesh = std::get_if<sim::MeshFile>(&solid.shape);
    if (mesh == nullptr) continue;
    const std::string path = "solids[" + std::to_string(i) + "]";
    const sim::Vec3& r = solid.rotateDegrees;
    if (r[0] != 0.0 || r[1] != 0.0 || r[2] != 0.0)
      throw InputError(scene.file.string(), path + ".rotate",
                       "[0, 0, 0] for a mesh solid (rotation is applied to boxes only; rotate the mesh file)",
                       "a rotation");
    loadMesh(*mesh, MeshPlacement{solid.scale, solid.translate}, scene, path + ".mesh", true);
  }
}

}  // namespace fluidsound::io
