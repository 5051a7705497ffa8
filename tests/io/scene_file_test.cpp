// tests/io/scene_file_test.cpp — `fluidsound.scene/1`: a scene with every field parses into the
// records field by field, absent fields take their documented defaults, the example scenes parse,
// and every kind of bad input gives one line naming the file, the JSON path and the expectation.
#include "io/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "io/input_error.h"
#include "support/input_error_expectations.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::TempFolder;

/// The repository root, for the example scenes (CMake defines it; else relative to this file).
fs::path sourceDir() {
#ifdef FLUIDSOUND_SOURCE_DIR
  return FLUIDSOUND_SOURCE_DIR;
#else
  return fs::path(__FILE__).parent_path().parent_path().parent_path();
#endif
}

/// A scene using every field except meshes (which need files; see the TempFolder tests).
json fullScene() {
  return json::parse(R"({
    "format": "fluidsound.scene/1",
    "domain": { "min": [0, 0, 0], "max": [0.6, 0.3, 0.1], "cell": 0.005, "open": ["+y", "-x"] },
    "gravity": [0, -9.8, 0.5],
    "time": { "duration": 2.0, "fps": 60, "cfl": 2.5 },
    "seed": 42,
    "liquid": [ { "box": { "min": [0, 0, 0], "max": [0.1, 0.2, 0.1] } },
                { "sphere": { "center": [0.3, 0.05, 0.05], "radius": 0.02 },
                  "velocity": [0, -2, 0] } ],
    "emitters": [ { "disk": { "center": [0.3, 0.25, 0.05], "normal": [0, -2, 0],
                              "radius": 0.004 },
                    "speed": 1.0, "start": 0.25, "end": 1.5 },
                  { "disk": { "center": [0.1, 0.25, 0.05], "normal": [3, 0, 4],
                              "radius": 0.002 },
                    "speed": 0.5 } ],
    "solids": [ { "box": { "min": [0.2, 0, 0], "max": [0.25, 0.05, 0.1] },
                  "scale": 2, "translate": [0.01, 0, 0], "rotate": [0, 0, 15] },
                { "sphere": { "center": [0.3, 0.2, 0.05], "radius": 0.01 },
                  "path": [ { "t": 0.0, "translate": [0, 0, 0] },
                            { "t": 0.5, "translate": [0, -0.15, 0] } ] } ],
    "listeners": [ { "name": "left", "position": [0.25, 0.4, 0.3] },
                   { "name": "right", "position": [0.35, 0.4, 0.3] } ],
    "audio": { "sample_rate": 44100 },
    "solver": { "transfer": "flip", "flip_ratio": 0.9, "particles_per_cell": 4,
                "pressure_tolerance": 1e-5, "max_pressure_iterations": 200 }
  })");
}

/// Only what is required.
json minimalScene() {
  return json::parse(R"({
    "format": "fluidsound.scene/1",
    "domain": { "min": [-0.1, 0, 0], "max": [0.3, 0.2, 0.1], "cell": 0.01 },
    "time": { "duration": 1.5 }
  })");
}

/// The InputError that parsing `text` as tank.json throws (a test failure if none).
InputError parseError(const std::string& text) {
  return test::inputErrorOf([](const std::string& t) { parseScene(t, "tank.json"); }, text);
}

/// The error is one line that names tank.json, exactly `field`, and contains `expected`.
void expectError(const InputError& error, const std::string& field, const std::string& expected) {
  test::expectInputError(error, "tank.json", field, expected, test::ExpectedAt::RightAfterHead);
}

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

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
  expected.listeners = {{"left", {0.25, 0.4, 0.3}}, {"right", {0.35, 0.4, 0.3}}};
  expected.sampleRate = 44100;
  expected.solver = {sim::TransferScheme::Flip, 0.9, 4, 1e-5, 200};

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
  EXPECT_EQ(scene.gravity, (sim::Vec3{0, -9.81, 0}));
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
  // open-topped 0.4 × 0.4 × 0.2 m tank, cells of 8 mm, default listener.
  const sim::Scene scene = readScene(sourceDir() / "scenes" / "sphere_drop.scene.json");
  EXPECT_EQ(scene.grid().cells, (sim::Index3{50, 50, 25}));
  EXPECT_EQ(scene.domain.open, (std::array<bool, 6>{false, false, false, true, false, false}));
  ASSERT_EQ(scene.liquid.size(), 2u);
  EXPECT_EQ(scene.liquid[0].shape, (sim::Shape{sim::Box{{0, 0, 0}, {0.4, 0.1, 0.2}}}));
  EXPECT_EQ(scene.liquid[1].shape, (sim::Shape{sim::Sphere{{0.2, 0.25, 0.1}, 0.04}}));
  EXPECT_EQ(scene.time.duration, 2.0);
  ASSERT_EQ(scene.listeners.size(), 1u);
  EXPECT_EQ(scene.listeners[0].name, "listener");
}

// ---- bad input: one test per kind of error -----------------------------------------------------

TEST(SceneFile, MalformedJsonGivesTheParserMessage) {
  const InputError error = parseError(R"({"format": "fluidsound.scene/1", "domain" {}})");
  expectError(error, "", "valid JSON, found parse error at line 1, column 43");
  EXPECT_EQ(std::string(error.what()).find("[json.exception"), std::string::npos) << error.what();
}

TEST(SceneFile, OverflowingNumberIsInvalidJson) {
  std::string text = minimalScene().dump();
  text.replace(text.find("1.5"), 3, "1e999");
  expectError(parseError(text), "", "valid JSON, found number overflow parsing '1e999'");
}

TEST(SceneFile, KeyGivenTwiceIsNamedWithItsPath) {
  const InputError error = parseError(R"({"format": "fluidsound.scene/1",
    "domain": {"min": [0, 0, 0], "max": [1, 1, 1], "cell": 0.1, "cell": 0.2},
    "time": {"duration": 1}})");
  expectError(error, "domain.cell",
              R"(each key at most once in an object, found "cell" a second time)");
}

TEST(SceneFile, KeyGivenTwiceInsideAnArrayItemIsNamedWithItsIndex) {
  const InputError error = parseError(R"({"format": "fluidsound.scene/1",
    "liquid": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}},
               {"sphere": {"center": [0, 0, 0], "radius": 1}, "velocity": [0, 0, 0],
                "velocity": [1, 0, 0]}]})");
  expectError(error, "liquid[1].velocity", "each key at most once in an object");
}

TEST(SceneFile, TopLevelArrayIsRejected) {
  expectError(parseError("[1, 2]"), "",
              "a JSON object (a fluidsound.scene/1 document), found an array of 2 values");
}

TEST(SceneFile, WrongFormatTagIsReportedBeforeAnythingElse) {
  // A bubble-track file given as a scene: the tag is the problem, not its unknown keys.
  const InputError error =
      parseError(R"({"format": "fluidsound.bubbles/1", "bubbles": [], "sample_rate": 48000})");
  EXPECT_STREQ(error.what(),
               R"(tank.json: format: expected "fluidsound.scene/1", found "fluidsound.bubbles/1")");
}

TEST(SceneFile, MissingFormatTagIsNamed) {
  json document = minimalScene();
  document.erase("format");
  expectError(parseError(document.dump()), "format",
              R"("fluidsound.scene/1", found nothing (required))");
}

TEST(SceneFile, MissingDomainIsNamed) {
  json document = minimalScene();
  document.erase("domain");
  expectError(parseError(document.dump()), "domain",
              "an object with min, max and cell, found nothing (required)");
}

TEST(SceneFile, MissingTimeIsNamed) {
  json document = minimalScene();
  document.erase("time");
  expectError(parseError(document.dump()), "time",
              "an object with duration (seconds), found nothing (required)");
}

TEST(SceneFile, DomainMaxNotAboveMinIsNamedPerAxis) {
  json document = minimalScene();
  document["domain"]["max"][1] = 0;
  expectError(parseError(document.dump()), "domain.max[1]",
              "a number > min[1] = 0.0 (metres), found 0");
}

TEST(SceneFile, NonPositiveCellIsNamed) {
  json document = minimalScene();
  document["domain"]["cell"] = 0;
  expectError(parseError(document.dump()), "domain.cell", "a number > 0 (metres), found 0");
  document["domain"]["cell"] = -0.01;
  expectError(parseError(document.dump()), "domain.cell", "a number > 0 (metres), found -0.01");
}

TEST(SceneFile, CellNotDividingTheExtentSuggestsTheNearestWholeCount) {
  // Extent along x is 0.4 m; 0.4 / 0.03 = 13.33 cells, nearest whole count 13: 0.4/13 m.
  json document = minimalScene();
  document["domain"]["max"] = {0.3, 0.3, 0.3};
  document["domain"]["cell"] = 0.03;
  const InputError error = parseError(document.dump());
  expectError(error, "domain.cell",
              "a cell size (metres) that divides the extent along x (0.4 m) into a whole number "
              "of cells, such as 0.03076923077 (13 cells), found 0.03 (13.3333 cells)");
}

TEST(SceneFile, CellGivingMoreThan1024CellsIsNamed) {
  json document = minimalScene();
  document["domain"]["cell"] = 0.0001;  // 4000 cells along x
  expectError(parseError(document.dump()), "domain.cell",
              "a cell size (metres) giving 2 to 1024 cells per axis, found 0.0001 (4000 cells "
              "along x)");
}

TEST(SceneFile, CellGivingFewerThanTwoCellsIsNamed) {
  json document = minimalScene();
  document["domain"]["cell"] = 0.1;  // 4 along x, 2 along y, 1 along z
  expectError(parseError(document.dump()), "domain.cell",
              "a cell size (metres) giving 2 to 1024 cells per axis, found 0.1 (1 cell along z)");
}

TEST(SceneFile, UnknownOpenFaceNameIsNamed) {
  json document = minimalScene();
  document["domain"]["open"] = {"+y", "top"};
  expectError(parseError(document.dump()), "domain.open[1]",
              R"(one of "-x", "+x", "-y", "+y", "-z", "+z", found "top")");
}

TEST(SceneFile, DuplicateOpenFaceIsNamed) {
  json document = minimalScene();
  document["domain"]["open"] = {"+y", "-x", "+y"};
  expectError(parseError(document.dump()), "domain.open[2]",
              R"(a face not listed before (domain.open[0] is "+y"), found "+y")");
}

TEST(SceneFile, OpenThatIsNotAnArrayIsNamed) {
  json document = minimalScene();
  document["domain"]["open"] = "+y";
  expectError(parseError(document.dump()), "domain.open", "an array of face names from");
}

TEST(SceneFile, NegativeDurationIsNamed) {
  json document = minimalScene();
  document["time"]["duration"] = -1;
  expectError(parseError(document.dump()), "time.duration", "a number > 0 (seconds), found -1");
}

TEST(SceneFile, NonPositiveFpsIsNamed) {
  json document = minimalScene();
  document["time"]["fps"] = 0;
  expectError(parseError(document.dump()), "time.fps", "a number > 0 (frames per second), found 0");
}

TEST(SceneFile, NonIntegerSeedIsNamed) {
  json document = minimalScene();
  document["seed"] = 1.5;
  expectError(parseError(document.dump()), "seed", "an integer >= 0, found 1.5");
  document["seed"] = -3;
  expectError(parseError(document.dump()), "seed", "an integer >= 0, found -3");
  document["seed"] = "7";
  expectError(parseError(document.dump()), "seed", R"(an integer >= 0, found "7")");
}

TEST(SceneFile, VectorOfWrongLengthIsNamed) {
  json document = minimalScene();
  document["gravity"] = {0, -9.81};
  expectError(parseError(document.dump()), "gravity",
              "an array of 3 numbers [x, y, z] (m/s^2), found an array of 2 values");
}

TEST(SceneFile, NonNumericVectorComponentIsNamed) {
  json document = minimalScene();
  document["domain"]["min"][2] = nullptr;
  expectError(parseError(document.dump()), "domain.min[2]", "a number (metres), found null");
}

TEST(SceneFile, LiquidItemWithTwoShapesIsNamed) {
  json document = minimalScene();
  document["liquid"] = json::array();
  document["liquid"].push_back({{"box", {{"min", {0, 0, 0}}, {"max", {1, 1, 1}}}}});
  document["liquid"].push_back({{"box", {{"min", {0, 0, 0}}, {"max", {1, 1, 1}}}},
                                {"sphere", {{"center", {0, 0, 0}}, {"radius", 1}}}});
  expectError(parseError(document.dump()), "liquid[1]",
              "exactly one shape: box, sphere or mesh, found box and sphere");
}

TEST(SceneFile, LiquidItemWithoutShapeIsNamed) {
  json document = minimalScene();
  document["liquid"] = {{{"velocity", {0, -1, 0}}}};
  expectError(parseError(document.dump()), "liquid[0]",
              "exactly one shape: box, sphere or mesh, found none of them");
}

TEST(SceneFile, LiquidBoxWithMinNotBelowMaxIsNamed) {
  json document = minimalScene();
  document["liquid"] = {{{"box", {{"min", {0, 0.2, 0}}, {"max", {0.1, 0.1, 0.1}}}}}};
  expectError(parseError(document.dump()), "liquid[0].box.max[1]",
              "a number > min[1] = 0.2 (metres), found 0.1");
}

TEST(SceneFile, NegativeSphereRadiusIsNamed) {
  json document = minimalScene();
  document["liquid"] = {{{"sphere", {{"center", {0, 0, 0}}, {"radius", -0.02}}}}};
  expectError(parseError(document.dump()), "liquid[0].sphere.radius",
              "a number > 0 (metres), found -0.02");
}

TEST(SceneFile, MissingMeshFileNamesTheLiquidItem) {
  TempFolder folder;
  json document = minimalScene();
  document["liquid"] = {{{"mesh", "pool.obj"}}};
  const fs::path sceneFile = folder.path() / "tank.json";
  writeFile(sceneFile, document.dump());
  try {
    readScene(sceneFile);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), sceneFile.string());
    EXPECT_EQ(error.field(), "liquid[0].mesh");
    EXPECT_EQ(std::string(error.what()),
              sceneFile.string() +
                  ": liquid[0].mesh: expected the path of a readable mesh file (OBJ or PLY; "
                  "relative to the scene file's folder), found \"pool.obj\" (" +
                  (folder.path() / "pool.obj").string() + ": no such file)");
  }
}

TEST(SceneFile, MeshPathThatIsAFolderNamesTheSolid) {
  TempFolder folder;
  fs::create_directories(folder.path() / "glass.obj");
  json document = minimalScene();
  document["solids"] = {{{"mesh", "glass.obj"}}};
  try {
    parseScene(document.dump(), folder.path() / "tank.json");
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "solids[0].mesh");
    EXPECT_EQ(error.found(),
              "\"glass.obj\" (" + (folder.path() / "glass.obj").string() + ": a folder)");
  }
}

TEST(SceneFile, EmitterWithZeroRadiusIsNamed) {
  json document = fullScene();
  document["emitters"][1]["disk"]["radius"] = 0;
  expectError(parseError(document.dump()), "emitters[1].disk.radius",
              "a number > 0 (metres), found 0");
}

TEST(SceneFile, EmitterWithZeroNormalIsNamed) {
  json document = fullScene();
  document["emitters"][0]["disk"]["normal"] = {0, 0, 0};
  expectError(parseError(document.dump()), "emitters[0].disk.normal",
              "a non-zero direction [x, y, z], found [0,0,0]");
}

TEST(SceneFile, EmitterEndNotAfterStartIsNamed) {
  json document = fullScene();
  document["emitters"][0]["end"] = 0.25;  // equal to start
  expectError(parseError(document.dump()), "emitters[0].end",
              "a number > start = 0.25 (seconds), found 0.25");
}

TEST(SceneFile, EmitterStartingAfterTheDefaultEndIsNamed) {
  json document = fullScene();
  document["emitters"][1]["start"] = 2.0;  // no "end": it defaults to time.duration = 2
  expectError(parseError(document.dump()), "emitters[1].start",
              "a number < time.duration = 2.0 (seconds; the default end), found 2.0");
}

TEST(SceneFile, EmitterWithoutSpeedIsNamed) {
  json document = fullScene();
  document["emitters"][0].erase("speed");
  expectError(parseError(document.dump()), "emitters[0].speed",
              "a number > 0 (m/s), found nothing (required)");
}

TEST(SceneFile, UnsortedPathKeysNameTheKeyOutOfOrder) {
  json document = fullScene();
  document["solids"][1]["path"].push_back({{"t", 0.4}, {"translate", {0, 0, 0}}});
  expectError(parseError(document.dump()), "solids[1].path[2].t",
              "a time greater than path[1].t = 0.5 (keys in time order; seconds), found 0.4");
}

TEST(SceneFile, NonPositiveSolidScaleIsNamed) {
  json document = fullScene();
  document["solids"][0]["scale"] = 0;
  expectError(parseError(document.dump()), "solids[0].scale",
              "a number > 0 (scale factor), found 0");
}

TEST(SceneFile, UnknownKeySuggestsTheClosestKnownKey) {
  json document = fullScene();
  document["solids"][0]["rotation"] = {0, 0, 10};
  expectError(parseError(document.dump()), "solids[0].rotation",
              "one of box, sphere, mesh, scale, translate, rotate, path (did you mean 'rotate'?), "
              "found an unknown key");
}

TEST(SceneFile, UnknownTopLevelKeySuggestsTheClosestKnownKey) {
  json document = minimalScene();
  document["gravty"] = {0, -9.81, 0};
  expectError(parseError(document.dump()), "gravty",
              "one of format, domain, gravity, time, seed, liquid, emitters, solids, listeners, "
              "audio, solver (did you mean 'gravity'?), found an unknown key");
}

TEST(SceneFile, UnknownKeyWithoutNearMatchListsTheKnownKeys) {
  json document = minimalScene();
  document["domain"]["colour"] = "blue";
  const InputError error = parseError(document.dump());
  EXPECT_STREQ(
      error.what(),
      "tank.json: domain.colour: expected one of min, max, cell, open, found an unknown key");
}

TEST(SceneFile, ExtensionStyleKeysAreUnknownKeys) {
  // Unlike fluidsound.bubbles/1, a scene has no x_ extension keys: a typo must not pass.
  json document = minimalScene();
  document["x_note"] = "hello";
  expectError(parseError(document.dump()), "x_note", "one of format, domain");
}

TEST(SceneFile, DuplicateListenerNamesAreNamed) {
  json document = fullScene();
  document["listeners"][1]["name"] = "left";
  expectError(
      parseError(document.dump()), "listeners[1].name",
      R"(a name not used by another listener (listeners[0].name is the same), found "left")");
}

TEST(SceneFile, EmptyListenerNameIsNamed) {
  json document = fullScene();
  document["listeners"][0]["name"] = "";
  expectError(parseError(document.dump()), "listeners[0].name",
              R"(a non-empty string (the channel's name), found "")");
}

TEST(SceneFile, EmptyListenerListIsNamed) {
  json document = fullScene();
  document["listeners"] = json::array();
  expectError(parseError(document.dump()), "listeners",
              "an array of 1 or more listeners {name, position} (omit it for the default), found "
              "an empty array");
}

TEST(SceneFile, SampleRateOutOfRangeIsNamed) {
  json document = fullScene();
  document["audio"]["sample_rate"] = 4000;
  expectError(parseError(document.dump()), "audio.sample_rate",
              "an integer from 8000 to 768000 (Hz), found 4000");
  document["audio"]["sample_rate"] = 1000000;
  expectError(parseError(document.dump()), "audio.sample_rate",
              "an integer from 8000 to 768000 (Hz), found 1000000");
  document["audio"]["sample_rate"] = 44100.5;  // audio files store whole rates
  expectError(parseError(document.dump()), "audio.sample_rate",
              "an integer from 8000 to 768000 (Hz), found 44100.5");
}

TEST(SceneFile, BadSolverTransferIsNamed) {
  json document = fullScene();
  document["solver"]["transfer"] = "pic";
  expectError(parseError(document.dump()), "solver.transfer",
              R"("apic" or "flip" (PIC is "flip" with flip_ratio 0), found "pic")");
  document["solver"]["transfer"] = "splat";
  expectError(parseError(document.dump()), "solver.transfer", R"("apic" or "flip", found "splat")");
  document["solver"]["transfer"] = "FLIP";
  expectError(parseError(document.dump()), "solver.transfer",
              R"("apic" or "flip" (did you mean "flip"?), found "FLIP")");
}

TEST(SceneFile, SolverValuesOutOfRangeAreNamed) {
  json document = fullScene();
  document["solver"]["flip_ratio"] = 1.5;
  expectError(parseError(document.dump()), "solver.flip_ratio",
              "a number from 0 to 1 (FLIP share of the FLIP/PIC blend), found 1.5");
  document = fullScene();
  document["solver"]["particles_per_cell"] = 65;
  expectError(parseError(document.dump()), "solver.particles_per_cell",
              "an integer from 1 to 64, found 65");
  document = fullScene();
  document["solver"]["pressure_tolerance"] = 0.1;
  expectError(parseError(document.dump()), "solver.pressure_tolerance",
              "a number > 0 and <= 0.01 (relative residual), found 0.1");
  document = fullScene();
  document["solver"]["max_pressure_iterations"] = 0;
  expectError(parseError(document.dump()), "solver.max_pressure_iterations",
              "an integer from 1 to 2147483647, found 0");
}

TEST(SceneFile, MissingFileIsAnInputErrorNamingIt) {
  TempFolder folder;
  const fs::path path = folder.path() / "nope.scene.json";
  try {
    readScene(path);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              path.string() + ": expected a readable file, found no such file");
  }
}

TEST(SceneFile, FolderIsNotAReadableFile) {
  TempFolder folder;
  try {
    readScene(folder.path());
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              folder.path().string() + ": expected a readable file, found a folder");
  }
}

}  // namespace
}  // namespace fluidsound::io
