// tests/sim/mesh_tank_rest_test.cpp — still water in tanks made of meshes stays still: issue 5's
// static-mesh-wall point (the example basins) and issue 4's spherical bowl. The scenes are the
// files in scenes/ (docs/scenes.md), loaded as `fluidsound simulate` loads them, at their own
// 5 mm cells, for 2 s.
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "io/scene_file.h"
#include "io/scene_meshes.h"
#include "support/rest_measure.h"

namespace fluidsound::sim {
namespace {

Scene exampleScene(const std::string& name) {
  Scene scene =
      io::readScene(std::string(FLUIDSOUND_SOURCE_DIR) + "/scenes/" + name + ".scene.json");
  io::loadSceneMeshes(scene);
  return scene;
}

/// Checks the rest criteria on the scene after 2 s and prints the measures.
void expectAtRest(const std::string& name) {
  const Scene scene = exampleScene(name);
  const test::RestMeasure m = test::restAfter(scene, 2.0);
  EXPECT_LT(m.maxSpeed, 1e-3);
  EXPECT_LT(m.heightSpread, 0.1 * scene.domain.cell);
  EXPECT_GT(m.columns, 100);
  std::cout << "[ measured ] " << name << ": max speed " << m.maxSpeed << " m/s, height spread "
            << m.heightSpread / scene.domain.cell << " cell over " << m.columns << " columns\n";
}

// Claim (issue 5): a tank built from a mesh holds still water at rest as the primitive tanks do:
// after 2 s the fastest particle moves at < 1 mm/s and the surface height varies by < 0.1 cell.
// scenes/still_basin: the basin mesh with its water as a mesh region whose sides and bottom lie
// on the basin's walls, all on cell planes. Before the level set started from the region's free
// faces only (sim/fluid/region_free_surface.h), those faces read the wall cells ¼–⅜ cell shallow
// and the water moved at 4.9 mm/s after 2 s. Measured: about 1e-8 m/s, spread about 0. Reference:
// rest. Tolerance: the 1 mm/s and 0.1 cell (issue 4's figures).
TEST(MeshTankRest, BasinWithMeshWaterStaysAtRest) { expectAtRest("still_basin"); }

// Claim (issue 5): the same with the basin moved 1.7 mm in x and 1.3 mm in z, so its walls cut
// the cells, and the water a box whose faces lie on the moved walls (the free-box rule of
// LiquidLevelSet; before it, 7.0 mm/s). Measured: about 4e-8 m/s.
// Reference: rest. Tolerance: the issue's.
TEST(MeshTankRest, BasinOffTheCellPlanesStaysAtRest) { expectAtRest("still_basin_off_grid"); }

// Claim (issue 4): still water in a spherical bowl — a concave curved wall, the inside of a
// hemisphere of radius 5 cm (scenes/meshes/bowl.obj; a primitive sphere solid is convex, so the
// bowl is a mesh) — stays at rest: < 1 mm/s and a spread < 0.1 cell after 2 s. The water is a box
// whose faces lie inside the bowl's material, up to 1.5 cm below the rim. Measured: about 5e-8
// m/s. Reference: rest. Tolerance: the issue's.
TEST(MeshTankRest, WaterInASphericalBowlStaysAtRest) { expectAtRest("still_bowl"); }

}  // namespace
}  // namespace fluidsound::sim
