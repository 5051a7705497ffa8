// tests/io/scene_file_test.cpp — `fluidsound.scene/1`: a scene with every field parses into the
// records field by field, absent fields take their documented defaults, the example scenes parse.
#include "io/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "io/scene_documents.h"

namespace fluidsound::io {
namespace {

using namespace scene_test;

// ---- valid input --------------------------------------------------------------------------------

TEST(SceneFile, EveryFieldReachesItsRecord) {
  // Claim: each field of a full scene lands in its record, with meshes resolved against the
  // scene file's folder and the emitter normals normalised; Scene's operator== compares all.
  TempFolder folder;
  fs::create_directories(folder.path() / "meshes");
  writeFile(folder.path() / "meshes" / "pool.obj", "v 0 0 0\n");
  writeFile(folder.path() / "glass.ply", "ply\n");
  json document = fullScene();
  document["liquid"].push_back({{"mesh", "meshes/pool.obj"}, {"velocity", {1, 0, 0}}});
  document["solids"].push_back({{"mesh", "./glass.ply"}, {"translate", {0.3, 0, 0.05}}});
  const fs::path sceneFile = folder.path() / "scene.json";
  writeFile(sceneFile, document.dump(2));

  sim::Scene expected;
  expected.file = sceneFile;
  expected.domain = {{0, 0, 0}, {0.6, 0.3, 0.1}, 0.005, {true, false, false, true, false, false}};
  expected.gravity = {0, -9.8, 0.5};
  expected.time = {2.0, 60, 2.5};
  expected.seed = 42;
  expected.liquid = {{sim::Box{{0, 0, 0}, {0.1, 0.2, 0.1}}, {0, 0, 0}},
                     {sim::Sphere{{0.3, 0.05, 0.05}, 0.02}, {0, -2, 0}},
                     {sim::MeshFile{folder.path() / "meshes" / "pool.obj"}, {1, 0, 0}}};
  expected.emitters = {{{0.3, 0.25, 0.05}, {0, -1, 0}, 0.004, 1.0, 0.25, 1.5},
                       {{0.1, 0.25, 0.05}, {0.6, 0, 0.8}, 0.002, 0.5, 0.0, 2.0}};
  expected.solids = {
      {sim::Box{{0.2, 0, 0}, {0.25, 0.05, 0.1}}, 2.0, {0, 0, 15}, {0.01, 0, 0}, {}},
      {sim::Sphere{{0.3, 0.2, 0.05}, 0.01},
       1.0,
       {0, 0, 0},
       {0, 0, 0},
       {{0.0, {0, 0, 0}}, {0.5, {0, -0.15, 0}}}},
      {sim::MeshFile{folder.path() / "glass.ply"}, 1.0, {0, 0, 0}, {0.3, 0, 0.05}, {}}};
  expected.listeners = {{"left", {0.25, 0.4, 0.3}, std::nullopt}, {"right", {0.35, 0.4, 0.3}, std::nullopt}};
  expected.sampleRate = 44100;
  expected.solver = {sim::TransferScheme::Flip, 0.9, 4, 1e-5, 200, sim::SurfaceMethod::LevelSet};

  const sim::Scene scene = readScene(sceneFile);
  // Field by field first, so a failure says which part differs.
  EXPECT_EQ(scene.domain, expected.domain);
  EXPECT_EQ(scene.gravity, expected.gravity);
  EXPECT_EQ(scene.time, expected.time);
  EXPECT_EQ(scene.seed, expected.seed);
  EXPECT_EQ(scene.liquid, expected.liquid);
  // Normalised in double: [3, 0, 4]/5 is exact to rounding; compare with 1 ulp-scale margins.
  ASSERT_EQ(scene.emitters.size(), 2u);
  EXPECT_NEAR(scene.emitters[1].normal[0], 0.6, 1e-15);
  EXPECT_NEAR(scene.emitters[1].normal[2], 0.8, 1e-15);
  EXPECT_EQ(scene.emitters[0], expected.emitters[0]);
  sim::Emitter second = scene.emitters[1];
  second.normal = expected.emitters[1].normal;
  EXPECT_EQ(second, expected.emitters[1]);  // the other fields, end defaulting to the duration
  EXPECT_EQ(scene.solids, expected.solids);
  EXPECT_EQ(scene.listeners, expected.listeners);
  EXPECT_EQ(scene.sampleRate, expected.sampleRate);
  EXPECT_EQ(scene.solver, expected.solver);
  EXPECT_EQ(scene.file, sceneFile);
}

TEST(SceneFile, AbsentOptionalFieldsTakeTheirDefaults) {
  const sim::Scene scene = parseScene(minimalScene().dump(), "tank.json");
  EXPECT_EQ(scene.file, fs::path("tank.json"));
  EXPECT_EQ(scene.domain.open, (std::array<bool, 6>{}));  // closed box
  EXPECT_EQ(scene.gravity, (Vec3{0, -9.81, 0}));
  EXPECT_EQ(scene.time.duration, 1.5);
  EXPECT_EQ(scene.time.fps, 30.0);
  EXPECT_EQ(scene.time.cfl, 1.0);
  EXPECT_EQ(scene.seed, 1u);
  EXPECT_TRUE(scene.liquid.empty());
  EXPECT_TRUE(scene.emitters.empty());
  EXPECT_TRUE(scene.solids.empty());
  EXPECT_EQ(scene.sampleRate, 48000.0);
  EXPECT_EQ(scene.solver, sim::SolverSettings{});
  EXPECT_EQ(scene.solver.transfer, sim::TransferScheme::Apic);
  EXPECT_EQ(scene.solver.flipRatio, 0.95);
  EXPECT_EQ(scene.solver.particlesPerCell, 8);
  EXPECT_EQ(scene.solver.pressureTolerance, 1e-6);
  EXPECT_EQ(scene.solver.maxPressureIterations, 1000);
}

TEST(SceneFile, DefaultListenerIsHalfAMetreAboveTheDomainCentre) {
  // DESIGN.md: "one listener 0.5 m above the domain centre"; the domain is
  // [-0.1, 0.3] × [0, 0.2] × [0, 0.1], so its centre is (0.1, 0.1, 0.05).
  const sim::Scene scene = parseScene(minimalScene().dump(), "tank.json");
  ASSERT_EQ(scene.listeners.size(), 1u);
  EXPECT_EQ(scene.listeners[0].name, "listener");
  EXPECT_NEAR(scene.listeners[0].position[0], 0.1, 1e-15);
  EXPECT_NEAR(scene.listeners[0].position[1], 0.6, 1e-15);
  EXPECT_NEAR(scene.listeners[0].position[2], 0.05, 1e-15);
}

TEST(SceneFile, OpenFacesAreStoredInAxisOrderWhateverTheListOrder) {
  json document = minimalScene();
  document["domain"]["open"] = {"+z", "-y", "+x"};
  const sim::Scene scene = parseScene(document.dump(), "tank.json");
  EXPECT_EQ(scene.domain.open, (std::array<bool, 6>{false, true, true, false, false, true}));
}

TEST(SceneFile, IntegralNumbersWrittenWithAFractionAreIntegers) {
  // Tools that write every number as a double (7.0) must still be able to give the seed.
  json document = minimalScene();
  document["seed"] = 7.0;
  document["solver"] = {{"particles_per_cell", 16.0}};
  const sim::Scene scene = parseScene(document.dump(), "tank.json");
  EXPECT_EQ(scene.seed, 7u);
  EXPECT_EQ(scene.solver.particlesPerCell, 16);
}

TEST(SceneFile, DecimalExtentsWithinRoundingAreWholeCellCounts) {
  // 0.4 / 0.008 = 50.000000000000007 in binary: within the 1e-6 relative tolerance.
  json document = minimalScene();
  document["domain"] = {{"min", {0, 0, 0}}, {"max", {0.4, 0.4, 0.2}}, {"cell", 0.008}};
  const sim::GridGeometry grid = parseScene(document.dump(), "tank.json").grid();
  EXPECT_EQ(grid.cells, (sim::Index3{50, 50, 25}));
}

TEST(SceneFile, DamBreakExampleParses) {
  // scenes/dam_break.scene.json: a water column a = 0.1 m wide, 2a high, at the −x wall of a
  // closed 0.5 × 0.3 × 0.1 m box, cells of 1 cm, heard by a stereo pair.
  const sim::Scene scene = readScene(sourceDir() / "scenes" / "dam_break.scene.json");
  EXPECT_EQ(scene.grid().cells, (sim::Index3{50, 30, 10}));
  EXPECT_EQ(scene.domain.open, (std::array<bool, 6>{}));
  ASSERT_EQ(scene.liquid.size(), 1u);
  EXPECT_EQ(scene.liquid[0].shape, (sim::Shape{sim::Box{{0, 0, 0}, {0.1, 0.2, 0.1}}}));
  EXPECT_EQ(scene.time.duration, 3.0);
  EXPECT_EQ(scene.time.fps, 30.0);
  ASSERT_EQ(scene.listeners.size(), 2u);
  EXPECT_EQ(scene.listeners[0].name, "left");
  EXPECT_EQ(scene.listeners[1].name, "right");
}

TEST(SceneFile, SphereDropExampleParses) {
  // scenes/sphere_drop.scene.json: a 4 cm sphere centred 0.25 m up, over water 0.1 m deep in an
  // open-topped 0.4 × 0.4 × 0.2 m tank, cells of 8 mm, heard by a stereo pair.
  const sim::Scene scene = readScene(sourceDir() / "scenes" / "sphere_drop.scene.json");
  EXPECT_EQ(scene.grid().cells, (sim::Index3{50, 50, 25}));
  EXPECT_EQ(scene.domain.open, (std::array<bool, 6>{false, false, false, true, false, false}));
  ASSERT_EQ(scene.liquid.size(), 2u);
  EXPECT_EQ(scene.liquid[0].shape, (sim::Shape{sim::Box{{0, 0, 0}, {0.4, 0.1, 0.2}}}));
  EXPECT_EQ(scene.liquid[1].shape, (sim::Shape{sim::Sphere{{0.2, 0.25, 0.1}, 0.04}}));
  EXPECT_EQ(scene.time.duration, 2.0);
  ASSERT_EQ(scene.listeners.size(), 2u);
  EXPECT_EQ(scene.listeners[0].name, "left");
  EXPECT_EQ(scene.listeners[1].name, "right");
}

// ---- the cell-size override (`--cell`) ---------------------------------------------------

TEST(SceneFile, CellOverrideSetsTheGrid) {
  // Claim: withCellSize replaces domain.cell and nothing else; the grid follows (0.6 × 0.3 ×
  // 0.1 m at 1 cm: 60 × 30 × 10 cells; decimal sizes pass as for domain.cell: 0.1 / 0.004).
  const sim::Scene scene = parseScene(fullScene().dump(), "tank.json");
  sim::Scene coarse = withCellSize(scene, 0.01, "--cell");
  EXPECT_EQ(coarse.grid().cells, (sim::Index3{60, 30, 10}));
  EXPECT_EQ(withCellSize(scene, 0.004, "--cell").grid().cells, (sim::Index3{150, 75, 25}));
  coarse.domain.cell = scene.domain.cell;
  EXPECT_EQ(coarse, scene) << "only the cell size changes";
}

TEST(SceneFile, CellOverrideKeepsTheDomainRules) {
  // Claim: the override is checked by domain.cell's own rules, and the error names the option
  // instead of a file and JSON path. Reference: the messages of domain.cell (docs/scene.md,
  // "Errors"), for the 0.6 × 0.3 × 0.1 m domain of fullScene().
  const sim::Scene scene = parseScene(fullScene().dump(), "tank.json");
  const auto errorFor = [&scene](double cell) {
    return test::inputErrorOf(
        [&](const std::string&) { (void)withCellSize(scene, cell, "--cell"); }, std::to_string(cell));
  };
  EXPECT_STREQ(errorFor(0.007).what(),
               "--cell: expected a cell size (metres) that divides the extent along x (0.6 m) into a "
               "whole number of cells, such as 0.006976744186 (86 cells), found 0.007 (85.7143 "
               "cells)");
  EXPECT_STREQ(errorFor(0.0005).what(),
               "--cell: expected a cell size (metres) giving 2 to 1024 cells per axis, found "
               "0.0005 (1200 cells along x)");
  EXPECT_STREQ(errorFor(0.0).what(), "--cell: expected a number > 0 (metres), found 0");
  EXPECT_STREQ(errorFor(-0.01).what(), "--cell: expected a number > 0 (metres), found -0.01");
  EXPECT_EQ(errorFor(0.007).file(), "");
  EXPECT_EQ(errorFor(0.007).field(), "--cell");
}

}  // namespace
}  // namespace fluidsound::io
