// Tests of sim/fluid/scene_mesh_distances.h: the solver's mesh distances, computed from the scene
// record's triangles on whatever grid the solver has, one entry per solid and region.
#include "sim/fluid/scene_mesh_distances.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "sim/fluid/fluid_solver.h"
#include "sim/fluid/mesh_distance.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/region_free_surface.h"
#include "sim/fluid/solid_geometry.h"
#include "support/test_meshes.h"

namespace fluidsound::sim {
namespace {

/// A closed 20 × 12 × 8 cm box of `cell` cells with a box solid, a mesh solid (a 4 cm cube at
/// x = 10 cm) and a mesh liquid region (a 4 cm cube at the origin corner).
FluidScene sceneWithMeshes(double cell) {
  FluidScene scene;
  scene.domain.max = {0.2, 0.12, 0.08};
  scene.domain.cell = cell;
  scene.time.duration = 1.0;
  Solid box;
  box.shape = Box{{0.16, 0.0, 0.0}, {0.2, 0.02, 0.08}};
  scene.solids.push_back(box);
  Solid mesh;
  mesh.shape = MeshFile{"cube.obj", std::make_shared<const TriangleMesh>(
                                        test::boxMesh({0.1f, 0.0f, 0.02f}, {0.14f, 0.04f, 0.06f}))};
  scene.solids.push_back(mesh);
  scene.liquid.push_back({MeshFile{"water.obj", std::make_shared<const TriangleMesh>(test::boxMesh(
                                                    {0.0f, 0.0f, 0.0f}, {0.04f, 0.04f, 0.04f}))},
                          {}});
  return scene;
}

// Claim: each mesh's entry is meshNodeDistance of its triangles on the given grid, bit for bit,
// and a mesh region's free surface is regionFreeSurfaceAtCentres against the solids at t = 0; a
// box has an empty entry. Reference: the functions called directly. Tolerance: exact.
TEST(SceneMeshDistances, EachMeshIsSampledOnTheGrid) {
  const FluidScene scene = sceneWithMeshes(0.01);
  const GridGeometry grid = scene.grid();
  const SceneMeshDistances d = sceneMeshDistances(scene, grid);
  ASSERT_EQ(d.solids.size(), 2u);
  ASSERT_EQ(d.liquid.size(), 1u);
  EXPECT_EQ(d.solids[0].nodes.elementCount(), 0u);
  const auto& cube = *std::get<MeshFile>(scene.solids[1].shape).surface;
  EXPECT_EQ(d.solids[1].nodes.values(), meshNodeDistance(cube, MeshPlacement{}, grid).values());
  EXPECT_EQ(d.solids[1].freeSurfaceAtCentres.elementCount(), 0u);
  const auto& water = *std::get<MeshFile>(scene.liquid[0].shape).surface;
  EXPECT_EQ(d.liquid[0].nodes.values(), meshNodeDistance(water, MeshPlacement{}, grid).values());
  const Array3f solids = solidNodeDistance(grid, scene.domain, scene.solids, 0.0, d.solids);
  EXPECT_EQ(d.liquid[0].freeSurfaceAtCentres.values(),
            regionFreeSurfaceAtCentres(water, solids, grid).values());
}

// Claim: the record holds no grid, so a change of the cell size after the meshes are read needs no
// reloading: the solver at 1 cm and at 0.5 cm each sample the same triangles on their own grid,
// and seed the mesh region like the same box region. Reference: the box region's seeding.
// Tolerance: 1 % of the particles (points within float rounding of a face may fall either way).
TEST(SceneMeshDistances, TheCellSizeMayChangeAfterTheMeshesAreRead) {
  for (const double cell : {0.01, 0.005}) {
    const FluidScene scene = sceneWithMeshes(cell);
    const GridGeometry grid = scene.grid();
    const SceneMeshDistances d = sceneMeshDistances(scene, grid);
    EXPECT_EQ(d.solids[1].grid.cellSize, cell);
    EXPECT_EQ(d.solids[1].nodes.size(), grid.nodeCount());
    const Array3f solids = solidNodeDistance(grid, scene.domain, scene.solids, 0.0, d.solids);
    const std::vector<LiquidRegion> box{{Box{{0, 0, 0}, {0.04, 0.04, 0.04}}, {}}};
    const double fromMesh =
        static_cast<double>(seedLiquid(grid, scene.liquid, solids, 8, 3, d.liquid).size());
    const double fromBox = static_cast<double>(seedLiquid(grid, box, solids, 8, 3).size());
    EXPECT_NEAR(fromMesh, fromBox, 0.01 * fromBox) << "cell " << cell;
    const FluidSolver solver(scene);
    EXPECT_NEAR(static_cast<double>(solver.particles().size()), fromBox, 0.01 * fromBox)
        << "cell " << cell;
  }
}

// Bad input to the library: a mesh whose triangles were never read, and a mesh solid queried
// without its distance, are errors naming the file (not a silent empty field).
TEST(SceneMeshDistances, MissingTrianglesOrDistanceNameTheFile) {
  FluidScene scene = sceneWithMeshes(0.01);
  const FluidScene loaded = scene;
  std::get<MeshFile>(scene.solids[1].shape).surface.reset();
  try {
    (void)sceneMeshDistances(scene, scene.grid());
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cube.obj"), std::string::npos) << e.what();
  }
  try {
    (void)solidNodeDistance(loaded.grid(), loaded.domain, loaded.solids, 0.0);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cube.obj"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fluidsound::sim
