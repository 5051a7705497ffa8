// Tests of io/scene_meshes.h: a scene's meshes read and placed into the scene record, and the
// solver's distances from them (sim/fluid/scene_mesh_distances.h) standing where the primitives do.
#include "io/scene_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "io/input_error.h"
#include "sim/fluid/fluid_solver.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/scene_mesh_distances.h"
#include "sim/fluid/solid_geometry.h"
#include "support/input_error_expectations.h"
#include "support/temp_folder.h"
#include "support/test_meshes.h"

namespace fluidsound::io {
namespace {

constexpr double kCell = 0.01;  // h [m]

/// A closed 20 × 12 × 8 cell box, a mesh file in `folder` and the scene naming it.
sim::Scene sceneWithMeshFile(const std::filesystem::path& folder) {
  sim::Scene scene;
  scene.file = folder / "scene.json";
  scene.domain.max = {0.2, 0.12, 0.08};
  scene.domain.cell = kCell;
  scene.time.duration = 1.0;
  test::writeFile(folder / "block.obj", test::objText(test::boxMesh({0.0f, 0.0f, 0.0f}, {0.05f, 0.04f, 0.03f})));
  return scene;
}

// Claim: a box mesh solid, scaled and translated, stands exactly where the same primitive box
// does: equal node distances within a cell and a half of its surface, and equal face fractions,
// so the solver sees the same wall. Reference: the primitive box solid (exact distance).
// Tolerance: 1e-5 h near the surface (float rounding; io/mesh_distance.h's exact zone), 1e-4 in
// the open fractions.
TEST(SceneMeshes, MeshBoxSolidEqualsThePrimitiveBox) {
  test::TempFolder folder;
  sim::Scene scene = sceneWithMeshFile(folder.path());
  sim::Solid mesh;
  mesh.shape = sim::MeshFile{folder.path() / "block.obj", nullptr};
  mesh.scale = 2.0;
  mesh.translate = {0.043, 0.0, 0.021};
  scene.solids.push_back(mesh);
  loadSceneMeshes(scene);
  sim::Solid box;
  box.shape = sim::Box{{0.043, 0.0, 0.021}, {0.143, 0.08, 0.081}};
  const sim::GridGeometry grid = scene.grid();
  const sim::SceneMeshDistances meshes = sim::sceneMeshDistances(scene, grid);
  const sim::Array3f fromMesh =
      sim::solidNodeDistance(grid, scene.domain, scene.solids, 0.0, meshes.solids);
  const sim::Array3f fromBox = sim::solidNodeDistance(grid, scene.domain, std::span(&box, 1), 0.0);
  int compared = 0;
  for (std::size_t n = 0; n < fromBox.values().size(); ++n)
    if (std::abs(fromBox.values()[n]) < 1.5 * kCell) {
      ASSERT_NEAR(fromMesh.values()[n], fromBox.values()[n], 1e-5 * kCell) << "node " << n;
      ++compared;
    }
  EXPECT_GT(compared, 200);
  const auto openMesh = sim::faceOpenFractions(fromMesh, grid), openBox = sim::faceOpenFractions(fromBox, grid);
  for (int a = 0; a < 3; ++a)
    for (std::size_t f = 0; f < openBox[a].values().size(); ++f)
      ASSERT_NEAR(openMesh[a].values()[f], openBox[a].values()[f], 1e-4);
}

// Claim: a rotated box mesh solid (a sloped floor: 25° about z, then 10° about x) stands where
// the primitive box with the same scale, rotation and translation does — both turn about the
// centre of the scaled box (docs/scene.md, "Placement of a solid"). Reference: the primitive
// box's exact distance. Tolerance: 1e-4 h near the surface (float vertices after a rotation).
TEST(SceneMeshes, RotatedMeshBoxSolidEqualsTheRotatedPrimitiveBox) {
  test::TempFolder folder;
  sim::Scene scene = sceneWithMeshFile(folder.path());
  sim::Solid mesh;
  mesh.shape = sim::MeshFile{folder.path() / "block.obj", nullptr};
  mesh.scale = 2.0;
  mesh.rotateDegrees = {10.0, 0.0, 25.0};
  mesh.translate = {0.043, 0.0, 0.0};
  scene.solids.push_back(mesh);
  loadSceneMeshes(scene);
  sim::Solid box = mesh;
  box.shape = sim::Box{{0.0, 0.0, 0.0}, {0.05, 0.04, 0.03}};
  const sim::GridGeometry grid = scene.grid();
  const sim::SceneMeshDistances meshes = sim::sceneMeshDistances(scene, grid);
  const sim::Array3f fromMesh =
      sim::solidNodeDistance(grid, scene.domain, scene.solids, 0.0, meshes.solids);
  const sim::Array3f fromBox = sim::solidNodeDistance(grid, scene.domain, std::span(&box, 1), 0.0);
  int compared = 0;
  for (std::size_t n = 0; n < fromBox.values().size(); ++n)
    if (std::abs(fromBox.values()[n]) < 1.0 * kCell) {
      ASSERT_NEAR(fromMesh.values()[n], fromBox.values()[n], 1e-4 * kCell) << "node " << n;
      ++compared;
    }
  EXPECT_GT(compared, 200);
  // The ray queries see the same placed triangles: a vertical ray through the turned top face.
  const sim::TriangleMesh& surface = *std::get<sim::MeshFile>(scene.solids[0].shape).surface;
  float top = -1.0f;
  for (const auto& v : surface.vertices) top = std::max(top, v[1]);
  EXPECT_GT(top, 0.08f) << "a 25° turn lifts a corner of the 10 × 8 cm box above its height";
}

// Claim: a closed mesh liquid region seeds the particles the same box region seeds (the same
// jitter from the same seed, the same inside test up to float rounding on the faces).
// Reference: the box region. Tolerance: 0.1 % of the particles (points within float rounding of
// a face may fall either way).
TEST(SceneMeshes, MeshLiquidRegionSeedsLikeTheBox) {
  test::TempFolder folder;
  sim::Scene scene = sceneWithMeshFile(folder.path());
  scene.liquid.push_back({sim::MeshFile{folder.path() / "block.obj", nullptr}, {}});
  loadSceneMeshes(scene);
  const sim::GridGeometry grid = scene.grid();
  const sim::Array3f solid = sim::solidNodeDistance(grid, scene.domain, scene.solids, 0.0);
  const std::vector<sim::LiquidRegion> box{{sim::Box{{0, 0, 0}, {0.05, 0.04, 0.03}}, {}}};
  const sim::SceneMeshDistances meshes = sim::sceneMeshDistances(scene, grid);
  const std::size_t fromMesh =
      sim::seedLiquid(grid, scene.liquid, solid, 8, 7, meshes.liquid).size();
  const std::size_t fromBox = sim::seedLiquid(grid, box, solid, 8, 7).size();
  EXPECT_NEAR(static_cast<double>(fromMesh), static_cast<double>(fromBox), 0.001 * fromBox);
  EXPECT_NEAR(static_cast<double>(fromBox), 5 * 4 * 3 * 8, 0.05 * 480) << "the box holds 60 cells";
}

// Claim: a kinematic mesh solid's path shifts its distance field: at a time when the path has
// moved it by (2.5, 1, 0) cells, the distance at p equals the static one at p − shift.
// Reference: the static field. Tolerance: trilinear interpolation of a field that is linear near
// a face: 1e-4 h at nodes 0.5–1.2 h from the faces.
TEST(SceneMeshes, PathShiftsAMeshSolid) {
  test::TempFolder folder;
  sim::Scene scene = sceneWithMeshFile(folder.path());
  sim::Solid mesh;
  mesh.shape = sim::MeshFile{folder.path() / "block.obj", nullptr};
  mesh.translate = {0.06, 0.0, 0.02};
  mesh.path = {{0.0, {0, 0, 0}}, {1.0, {0.05, 0.02, 0.0}}};
  scene.solids.push_back(mesh);
  loadSceneMeshes(scene);
  const Vec3 shift{0.025, 0.01, 0.0};  // at t = 0.5
  const sim::GridGeometry grid = scene.grid();
  const sim::SceneMeshDistances meshes = sim::sceneMeshDistances(scene, grid);
  const sim::Array3f moved = sim::solidNodeDistance(
      grid,
      sim::Domain{scene.domain.min, scene.domain.max, kCell, {true, true, true, true, true, true}},
      scene.solids, 0.5, meshes.solids);
  int compared = 0;
  for (int k = 0; k <= grid.cells[2]; ++k)
    for (int j = 0; j <= grid.cells[1]; ++j)
      for (int i = 0; i <= grid.cells[0]; ++i) {
        const Vec3 p = grid.worldFromGrid({double(i), double(j), double(k)});
        const Vec3 back{p[0] - shift[0], p[1] - shift[1], p[2] - shift[2]};
        const double expected = sim::meshDistance(meshes.solids[0], back);  // the static field
        if (std::abs(expected) < 0.5 * kCell || std::abs(expected) > 1.2 * kCell) continue;
        ASSERT_NEAR(moved(i, j, k), expected, 1e-4 * kCell);
        ++compared;
      }
  EXPECT_GT(compared, 50);
}

// Claim: a dam break against a mesh obstacle runs as against a box: the projection converges,
// stays divergence-free, and no particle ends inside the obstacle.
// Reference: the obstacle's own distance. Tolerance: pushed-out particles land 0.05 h outside;
// 0.1 h allows the trilinear distance's error at the box's edges.
TEST(SceneMeshes, LiquidFlowsAroundAMeshObstacle) {
  test::TempFolder folder;
  sim::Scene scene = sceneWithMeshFile(folder.path());
  scene.liquid.push_back({sim::Box{{0, 0, 0}, {0.05, 0.1, 0.08}}, {}});
  sim::Solid mesh;
  mesh.shape = sim::MeshFile{folder.path() / "block.obj", nullptr};
  mesh.translate = {0.1, 0.0, 0.0};
  scene.solids.push_back(mesh);
  loadSceneMeshes(scene);
  sim::FluidSolver solver(scene);
  const sim::FrameStats stats = solver.advanceTo(0.4);
  EXPECT_TRUE(stats.pressureConverged);
  EXPECT_LT(stats.maxDivergence, 1e-4);
  const sim::MeshNodeDistance obstacle = sim::sceneMeshDistances(scene, solver.grid()).solids[0];
  for (const sim::Vec3f& x : solver.particles().position)
    ASSERT_GT(sim::meshDistance(obstacle, {x[0], x[1], x[2]}), -0.1 * kCell);
}

// Bad input: an open mesh names the field.
TEST(SceneMeshes, OpenMeshNamesTheField) {
  test::TempFolder folder;
  sim::Scene scene = sceneWithMeshFile(folder.path());
  sim::TriangleMesh open = test::boxMesh({0, 0, 0}, {0.05f, 0.04f, 0.03f});
  open.triangles.pop_back();
  test::writeFile(folder.path() / "open.obj", test::objText(open));
  sim::Solid mesh;
  mesh.shape = sim::MeshFile{folder.path() / "open.obj", nullptr};
  scene.solids.push_back(mesh);
  try {
    loadSceneMeshes(scene);
    FAIL() << "an open mesh was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "solids[0].mesh");
    EXPECT_NE(std::string(e.what()).find("closed"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fluidsound::io
