// Tests of the example scenes (scenes/*.scene.json, docs/scenes.md) and the meshes that
// tools/make_meshes.py writes into scenes/meshes/: every scene parses and loads its meshes, every
// mesh is closed and oriented outward, and the glass has the documented shape. (That the
// committed meshes equal what the script writes is the ctest ExampleMeshes.MatchTheirScript.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "io/mesh_file.h"
#include "io/scene_documents.h"
#include "io/scene_file.h"
#include "io/scene_meshes.h"

namespace fluidsound::io {
namespace {

using namespace scene_test;

/// The files in `folder` whose names end with `suffix`, sorted.
std::vector<fs::path> filesEndingWith(const fs::path& folder, const std::string& suffix) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && entry.path().filename().string().ends_with(suffix))
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Claim (issues 5, 6): every example scene parses, its meshes load (exist, read, closed) on its
// grid, and it is heard by a stereo pair "left"/"right" (and any binaural heads) in air above the
// domain — except glass_hidden's "right", at the table's height behind the glass on purpose
// (issue 20: a listener the glass hides). Reference: the rules of docs/scene.md and docs/scenes.md.
TEST(ExampleScenes, EverySceneParsesAndLoadsItsMeshes) {
  const std::vector<fs::path> scenes = filesEndingWith(sourceDir() / "scenes", ".scene.json");
  EXPECT_GE(scenes.size(), 6u)
      << "dam_break, glass_pour, pour_tank, sphere_drop, stone_drop, tap_drip";
  for (const fs::path& file : scenes) {
    SCOPED_TRACE(file.string());
    sim::Scene scene;
    ASSERT_NO_THROW(scene = readScene(file));
    ASSERT_NO_THROW(loadSceneMeshes(scene));
    for (const sim::Solid& solid : scene.solids)
      if (const auto* mesh = std::get_if<sim::MeshFile>(&solid.shape)) {
        ASSERT_TRUE(mesh->surface);
        EXPECT_FALSE(mesh->surface->triangles.empty());
      }
    ASSERT_GE(scene.listeners.size(), 2u);
    EXPECT_EQ(scene.listeners[0].name, "left");
    EXPECT_EQ(scene.listeners[1].name, "right");
    for (std::size_t l = 2; l < scene.listeners.size(); ++l)  // any more are binaural heads
      EXPECT_TRUE(scene.listeners[l].head) << scene.listeners[l].name;
    for (const sim::Listener& listener : scene.listeners) {
      if (!(file.filename() == "glass_hidden.scene.json" && listener.name == "right")) {
        EXPECT_GE(listener.position[1], scene.domain.max[1])
            << listener.name << " is not above the domain";
      }
    }
  }
}

// Claim: every mesh in scenes/meshes/ is closed (every edge shared by two triangles running along
// it in opposite directions) and oriented outward (positive signed volume). Reference: the rule
// of io/mesh_closedness.h, which the scenes' loader enforces.
TEST(ExampleMeshes, EveryMeshIsClosedAndOutward) {
  const std::vector<fs::path> meshes = filesEndingWith(sourceDir() / "scenes" / "meshes", ".obj");
  EXPECT_GE(meshes.size(), 2u) << "glass.obj and basin.obj at least";
  for (const fs::path& file : meshes) {
    SCOPED_TRACE(file.string());
    io::MeshClosedness closedness;
    ASSERT_NO_THROW(closedness = requireClosedMesh(readMeshFile(file), file));
    EXPECT_EQ(closedness.degenerateTriangles, 0u);
    EXPECT_GT(closedness.signedVolume, 0.0) << "inward";
  }
}

// Claim: glass.obj is the documented glass: origin at the centre of its base, axis +y, outer
// radius 0.032 m, height 0.100 m; an open cup whose material volume is that of the polygonal
// solid, 48-gon outer prism minus the 48-gon cavity above the 0.004 m base:
// V = A(0.032)·0.100 − A(0.030)·0.096 with A(r) = ½·48·r²·sin(2π/48) (≈ 50.12 cm³; a solid
// cylinder would hold ≈ 320 cm³, a cup without its floor ≈ 11 cm³ less). Tolerance: every vertex is
// off by at most √3/2·10⁻⁷ m (7 decimals in the file) plus float rounding (< 10⁻⁸ m at 3 cm), so
// the volume by at most the surface area (≈ 0.04 m²) times 1.1·10⁻⁷ m; bounds to 10⁻⁶ m.
TEST(ExampleMeshes, GlassHasTheDocumentedShape) {
  const fs::path file = sourceDir() / "scenes" / "meshes" / "glass.obj";
  const sim::TriangleMesh mesh = readMeshFile(file);
  std::array<double, 3> lo{1, 1, 1}, hi{-1, -1, -1};
  for (const auto& v : mesh.vertices)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], static_cast<double>(v[a]));
      hi[a] = std::max(hi[a], static_cast<double>(v[a]));
    }
  EXPECT_NEAR(hi[0], 0.032, 1e-6);
  EXPECT_NEAR(lo[0], -0.032, 1e-6);
  EXPECT_NEAR(lo[1], 0.0, 1e-6);
  EXPECT_NEAR(hi[1], 0.100, 1e-6);
  const auto polygonArea = [](double r) {
    return 0.5 * 48 * r * r * std::sin(2 * std::numbers::pi / 48);
  };
  const double expected = polygonArea(0.032) * 0.100 - polygonArea(0.030) * 0.096;
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    std::array<double, 3> e1{}, e2{};
    for (int a = 0; a < 3; ++a) {
      e1[a] = static_cast<double>(mesh.vertices[t[1]][a]) - mesh.vertices[t[0]][a];
      e2[a] = static_cast<double>(mesh.vertices[t[2]][a]) - mesh.vertices[t[0]][a];
    }
    const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
                 cz = e1[0] * e2[1] - e1[1] * e2[0];
    area += 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
  }
  const io::MeshClosedness closedness = requireClosedMesh(mesh, file);
  EXPECT_NEAR(closedness.signedVolume, expected, area * 1.1e-7)
      << "measured " << closedness.signedVolume << " m^3, expected " << expected << " m^3";
}

}  // namespace
}  // namespace fluidsound::io
