// tests/io/scene_file_errors_test.cpp — `fluidsound.scene/1`: every kind of bad input gives one
// line naming the file, the JSON path and the expectation.
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

// Claim: a scene nested 100 000 levels deep (200 KB; gigabytes if each open level held its path) is
// refused as it is read at the 65th level, naming that level's path and the limit (64).
TEST(SceneFile, NestingDeeperThanTheLimitIsRefusedWhereItIsHit) {
  const std::size_t levels = 100000;
  const InputError error = parseError(R"({"format": "fluidsound.scene/1", "liquid": [{"box": )" +
                                      std::string(levels, '[') + std::string(levels, ']') + "}]}");
  std::string field = "liquid[0].box";
  for (std::size_t level = 4; level <= 64; ++level) field += "[0]";  // levels 1–3: {, liquid, [0]
  expectError(error, field, "at most 64 nested arrays and objects, found a deeper array");
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
  expectError(parseError(document.dump()), "time.fps",
              "a number > 0 and <= 1000 (frames per second), found 0");
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
              "a number > 0 and <= 1000 (m/s; two thirds of the speed of sound in water), found nothing (required)");
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
              "one of format, domain, gravity, time, seed, liquid, emitters, solids, bodies, collision_samples, listeners, "
              "audio, solver, bubbles, transfer (did you mean 'gravity'?), found an unknown key");
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

// One channel per listener and the synthesizer renders at most 16 (acoustics::kMaxListeners):
// a 17th is refused where the scene is read, before any simulation (it failed in synth after it).
TEST(SceneFile, MoreListenersThanChannelsAreRefused) {
  json document = fullScene();
  json listeners = json::array();
  for (int i = 0; i < 17; ++i) {
    std::string name = "listener ";  // appended: g++ 12 warns falsely (-Wrestrict) on "literal" + string
    name.append(std::to_string(i));
    listeners.push_back({{"name", name}, {"position", {0.0, 1.0, 0.0}}});
  }
  document["listeners"] = listeners;
  expectError(parseError(document.dump()), "listeners",
              "at most 16 listeners (one channel each), found 17 listeners");
  listeners.erase(listeners.size() - 1);
  document["listeners"] = listeners;
  EXPECT_EQ(parseScene(document.dump(), "tank.json").listeners.size(), 16u) << "16 is the limit, not beyond it";
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
