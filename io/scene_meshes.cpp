// io/scene_meshes.cpp — see scene_meshes.h.
#include "io/scene_meshes.h"

#include <memory>
#include <string>

#include "io/input_error.h"
#include "io/mesh_distance.h"
#include "io/mesh_file.h"

namespace fluidsound::io {
namespace {
std::shared_ptr<const sim::MeshNodeDistance> loadDistance(const sim::MeshFile& file, const MeshPlacement& placement,
                                                          const sim::Scene& scene, const std::string& jsonPath) {
  const MeshReference reference{scene.file.string(), jsonPath};
  const sim::TriangleMesh mesh = readMeshFile(file.file, reference);
  requireClosedMesh(mesh, file.file, reference);
  auto distance = std::make_shared<sim::MeshNodeDistance>();
  distance->grid = scene.grid();
  distance->nodes = meshNodeDistance(mesh, placement, distance->grid);
  return distance;
}
}  // namespace

void loadSceneMeshes(sim::Scene& scene) {
  for (std::size_t i = 0; i < scene.liquid.size(); ++i)
    if (auto* mesh = std::get_if<sim::MeshFile>(&scene.liquid[i].shape))
      mesh->distance = loadDistance(*mesh, {}, scene, "liquid[" + std::to_string(i) + "].mesh");
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
    mesh->distance = loadDistance(*mesh, MeshPlacement{solid.scale, solid.translate}, scene, path + ".mesh");
  }
}

}  // namespace fluidsound::io
