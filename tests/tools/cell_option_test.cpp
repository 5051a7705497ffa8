// Tests of `--cell METRES` (tools/cell_option.h) on the real `fluidsound simulate` and `run`: the
// scene runs on the given cell size, meshes included; a size that breaks domain.cell's rules is
// one line naming `--cell`, exit 2, and nothing is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "support/command_runner.h"
#include "support/temp_folder.h"
#include "support/test_meshes.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

constexpr int kExitUsage = 2;  // docs/cli.md: bad command line (a value out of range)

/// A 0.24 × 0.16 × 0.04 m box at 2 cm cells (12 × 8 × 2) with a water column and a mesh block
/// (block.obj, beside the scene) standing on the floor; 2 frames at 30 fps.
constexpr const char* kScene = R"({
  "format": "fluidsound.scene/1",
  "domain": { "min": [0, 0, 0], "max": [0.24, 0.16, 0.04], "cell": 0.02 },
  "time": { "duration": 0.06, "fps": 30 },
  "liquid": [ { "box": { "min": [0, 0, 0], "max": [0.08, 0.12, 0.04] } } ],
  "solids": [ { "mesh": "block.obj", "translate": [0.16, 0, 0] } ]
})";

/// Writes WORK/scene.json and WORK/block.obj (a 4 × 4 × 4 cm box); returns the scene's path.
fs::path writeScene(const fs::path& work) {
  { std::ofstream(work / "scene.json") << kScene; }
  writeFile(work / "block.obj", objText(boxMesh({0.0f, 0.0f, 0.0f}, {0.04f, 0.04f, 0.04f})));
  return work / "scene.json";
}

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(std::string(std::istreambuf_iterator<char>(in), {}));
}

// Claim: `simulate --cell 0.01` simulates the 2 cm scene on 1 cm cells (24 × 16 × 4 = 1536
// cells), mesh solid included: the solver samples the mesh's distance on its own grid
// (sim/fluid/scene_mesh_distances.h), whatever the cell size was when the mesh was read. Reference:
// the report's settings.
TEST(CellOption, SimulateRunsOnTheGivenCellSize) {
  const TempFolder folder;
  const fs::path scene = writeScene(folder.path()), out = folder.path() / "out";
  const CommandOutcome result =
      runFluidsound({"simulate", scene.string(), "-o", out.string(), "--cell", "0.01", "--quiet"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const nlohmann::json report = readJson(out / "report.json");
  EXPECT_EQ(report["settings"]["cell_size"].get<double>(), 0.01);
  EXPECT_EQ(report["settings"]["cells"].get<double>(), 24.0 * 16 * 4);
}

struct BadCell {
  const char* name;
  const char* value;    ///< the text after --cell
  const char* message;  ///< the whole stderr line after "fluidsound: error: "
};

/// Each rule of domain.cell (docs/scene.md) for the 0.24 × 0.16 × 0.04 m domain.
const BadCell kBadCells[] = {
    {"zero", "0", "--cell: expected a number > 0 (metres), found 0"},
    {"negative", "-0.01", "--cell: expected a number > 0 (metres), found -0.01"},
    {"nan", "nan", "--cell: expected a number > 0 (metres), found nan"},
    {"infinite", "inf", "--cell: expected a number > 0 (metres), found inf"},
    {"overflowing", "1e999", "--cell: expected a number > 0 (metres), found inf"},
    {"not_dividing", "0.007",
     "--cell: expected a cell size (metres) that divides the extent along x (0.24 m) into a whole "
     "number of cells, such as 0.007058823529 (34 cells), found 0.007 (34.2857 cells)"},
    {"one_cell_along_z", "0.04",
     "--cell: expected a cell size (metres) giving 2 to 1024 cells per axis, found 0.04 (1 cell "
     "along z)"},
    {"too_many_cells", "0.0002",
     "--cell: expected a cell size (metres) giving 2 to 1024 cells per axis, found 0.0002 (1200 "
     "cells along x)"},
};

void PrintTo(const BadCell& row, std::ostream* out) { *out << row.name; }

class BadCellOption : public ::testing::TestWithParam<BadCell> {};

// Claim: for simulate and run alike, a --cell that breaks a rule of domain.cell is one line
// naming the option, what was expected and what was found, exit 2, and nothing is written
// (OUTDIR is not even made). Reference: the domain.cell messages of docs/scene.md.
TEST_P(BadCellOption, NamesTheOptionAndWritesNothing) {
  const BadCell& row = GetParam();
  for (const char* command : {"simulate", "run"}) {
    SCOPED_TRACE(command);
    const TempFolder folder;
    const fs::path scene = writeScene(folder.path()), out = folder.path() / "out";
    const CommandOutcome result = runFluidsound(
        {command, scene.string(), "-o", out.string(), "--cell", row.value, "--quiet"});
    EXPECT_EQ(result.exitCode, kExitUsage) << result.err;
    EXPECT_EQ(result.err, std::string("fluidsound: error: ") + row.message + "\n");
    EXPECT_FALSE(fs::exists(out));
  }
}

INSTANTIATE_TEST_SUITE_P(CellOption, BadCellOption, ::testing::ValuesIn(kBadCells),
                         [](const ::testing::TestParamInfo<BadCell>& info) {
                           return std::string(info.param.name);
                         });

// Claim: a grid whose arrays alone cannot fit in this machine's memory is refused before
// anything is written — 1024³ cells of a 10.24 cm cube at 0.1 mm need at least 250 GB at the
// solver's 250 B per cell (tools/solver_memory.h), more than any machine this runs on — with one
// line naming `--cell` (exit 2) when the option made it, `domain.cell` and the scene file (exit 3)
// when the file did. Reference: the cell count and the byte figure of the message.
TEST(CellOption, AGridLargerThanMemoryIsRefusedBeforeAnythingIsWritten) {
  constexpr int kExitBadInput = 3;  // docs/cli.md: a bad input file
  const TempFolder folder;
  const fs::path scene = folder.path() / "cube.json";
  const auto writeCube = [&](const char* cell) {
    std::ofstream(scene) << R"({ "format": "fluidsound.scene/1",
      "domain": { "min": [0, 0, 0], "max": [0.1024, 0.1024, 0.1024], "cell": )" << cell << R"( },
      "time": { "duration": 0.1, "fps": 30 } })";
  };
  const std::string counted = "found 0.0001 m: 1024 x 1024 x 1024 = 1.07e+09 cells, at least 250.0 GiB";
  writeCube("0.0128");
  for (const char* command : {"simulate", "run"}) {
    SCOPED_TRACE(command);
    const fs::path out = folder.path() / "out";
    const CommandOutcome byOption =
        runFluidsound({command, scene.string(), "-o", out.string(), "--cell", "0.0001", "--quiet"});
    EXPECT_EQ(byOption.exitCode, kExitUsage) << byOption.err;
    EXPECT_EQ(byOption.err.rfind("fluidsound: error: --cell: expected a cell size whose grid fits in this "
                                 "machine's ", 0), 0u) << byOption.err;
    EXPECT_NE(byOption.err.find(counted), std::string::npos) << byOption.err;
    EXPECT_EQ(std::count(byOption.err.begin(), byOption.err.end(), '\n'), 1) << byOption.err;
    EXPECT_FALSE(fs::exists(out));
  }
  writeCube("0.0001");
  const fs::path out = folder.path() / "out";
  const CommandOutcome byFile = runFluidsound({"simulate", scene.string(), "-o", out.string(), "--quiet"});
  EXPECT_EQ(byFile.exitCode, kExitBadInput) << byFile.err;
  EXPECT_EQ(byFile.err.rfind("fluidsound: error: " + scene.string() + ": domain.cell: expected a cell size whose "
                             "grid fits", 0), 0u) << byFile.err;
  EXPECT_NE(byFile.err.find(counted), std::string::npos) << byFile.err;
  EXPECT_FALSE(fs::exists(out));
}

// Claim: `run`'s stage hash includes the cell size it runs at: the same size as the file's
// (given or not) reuses every stage, another one simulates again (and so transfers and
// renders again). Reference: the report's `reused` flags and `cell_size`.
TEST(CellOption, RunSimulatesAgainWhenTheCellChanges) {
  const TempFolder folder;
  const fs::path scene = writeScene(folder.path()), out = folder.path() / "out";
  // Runs the pipeline, with `--cell CELL` unless `cell` is empty; returns the report's `run`.
  const auto run = [&](const std::string& cell) {
    const CommandOutcome result =
        cell.empty()
            ? runFluidsound({"run", scene.string(), "-o", out.string(), "--quiet"})
            : runFluidsound({"run", scene.string(), "-o", out.string(), "--quiet", "--cell", cell});
    EXPECT_EQ(result.exitCode, 0) << result.err;
    return readJson(out / "report.json")["run"];
  };
  EXPECT_FALSE(run("")["stages"]["simulate"]["reused"].get<bool>());
  nlohmann::json again = run("0.02");
  EXPECT_TRUE(again["stages"]["simulate"]["reused"].get<bool>()) << "0.02 m is the file's own cell";
  nlohmann::json finer = run("0.01");
  for (const char* stage : {"simulate", "transfer", "synth"})
    EXPECT_FALSE(finer["stages"][stage]["reused"].get<bool>()) << stage << " after --cell changed";
  EXPECT_EQ(finer["cell_size"].get<double>(), 0.01);
  EXPECT_TRUE(run("0.01")["stages"]["simulate"]["reused"].get<bool>()) << "unchanged --cell";
}

}  // namespace
}  // namespace fluidsound::test
