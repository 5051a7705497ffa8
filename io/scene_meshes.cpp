// io/scene_meshes.cpp — see scene_meshes.h.
#include "io/scene_meshes.h"

#include <algorithm>
#include <memory>
#include <string>
#include <utility>

#include "io/input_error.h"
#include "io/mesh_file.h"
#include "sim/fluid/solid_rotation.h"

namespace fluidsound::io {
namespace {
/// The mesh placed as a solid (docs/scene.md, "Placement of a solid", without the path): scaled
/// about the origin, rotated about the centre of its scaled bounding box, translated; in double,
/// then stored as float like the file's own coordinates.
sim::TriangleMesh placedMesh(sim::TriangleMesh mesh, double scale, const Vec3& rotateDegrees,
                             const Vec3& translate) {
  Vec3 lower{1e300, 1e300, 1e300}, upper{-1e300, -1e300, -1e300};
  for (const auto& v : mesh.vertices)
    for (int a = 0; a < 3; ++a) {
      lower[a] = std::min(lower[a], scale * v[a]);
      upper[a] = std::max(upper[a], scale * v[a]);
    }
  Vec3 centre{};
  for (int a = 0; a < 3; ++a) centre[a] = 0.5 * (lower[a] + upper[a]);
  for (auto& v : mesh.vertices) {
    const Vec3 turned = sim::rotateByEulerDegrees(
        {scale * v[0] - centre[0], scale * v[1] - centre[1], scale * v[2] - centre[2]},
        rotateDegrees);
    for (int a = 0; a < 3; ++a) v[a] = static_cast<float>(centre[a] + turned[a] + translate[a]);
  }
  return mesh;
}

/// Reads and checks the mesh `file` names, places it with `place` and keeps the placed triangles
/// in the record.
template <typename Place>
void loadMesh(sim::MeshFile& file, const Place& place, const sim::Scene& scene,
              const std::string& jsonPath) {
  const MeshReference reference{scene.file.string(), jsonPath};
  const sim::TriangleMesh mesh = place(readMeshFile(file.file, reference));
  requireClosedMesh(mesh, file.file, reference);
  file.surface = std::make_shared<const sim::TriangleMesh>(mesh);
}
}  // namespace

void loadSceneMeshes(sim::Scene& scene) {
  for (std::size_t i = 0; i < scene.liquid.size(); ++i)
    if (auto* mesh = std::get_if<sim::MeshFile>(&scene.liquid[i].shape))
      loadMesh(
          *mesh, [](sim::TriangleMesh m) { return m; }, scene,
          "liquid[" + std::to_string(i) + "].mesh");
  for (std::size_t i = 0; i < scene.solids.size(); ++i) {
    sim::Solid& solid = scene.solids[i];
    auto* mesh = std::get_if<sim::MeshFile>(&solid.shape);
    if (mesh == nullptr) continue;
    const auto place = [&solid](sim::TriangleMesh m) {
      return placedMesh(std::move(m), solid.scale, solid.rotateDegrees, solid.translate);
    };
    loadMesh(*mesh, place, scene, "solids[" + std::to_string(i) + "].mesh");
  }
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    sim::SceneBody& body = scene.bodies[i];
    auto* mesh = std::get_if<sim::MeshFile>(&body.shape);
    if (mesh == nullptr) continue;
    // A body's mesh stays in its own frame, scaled: the rigid-body stage places it by its pose.
    const auto place = [&body](sim::TriangleMesh m) { return placedMesh(std::move(m), body.scale, {}, {}); };
    loadMesh(*mesh, place, scene, "bodies[" + std::to_string(i) + "].mesh");
  }
}

}  // namespace fluidsound::io
