// Tests of tools/frame_water_grids.h: a frame `fluidsound simulate` wrote, as the geometric
// transfer's water grid — the solver's grid, φ at its cell centres, the solids' open face
// fractions at the frame's time and the domain's open sides.
#include "tools/frame_water_grids.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/input_error.h"
#include "io/scene_file.h"
#include "support/command_runner.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

// A 8 × 6 × 2 cell box (2 cm cells), open at the top, with water in the left quarter and a rigid
// box solid in the right third, x 0.10 … 0.16 m, y 0 … 0.06 m; two frames.
constexpr const char* kBoxScene = R"({
  "format": "fluidsound.scene/1",
  "domain": { "min": [0, 0, 0], "max": [0.16, 0.12, 0.04], "cell": 0.02, "open": ["+y"] },
  "time": { "duration": 0.034, "fps": 30 },
  "liquid": [ { "box": { "min": [0, 0, 0], "max": [0.06, 0.08, 0.04] } } ],
  "solids": [ { "box": { "min": [0.10, 0, 0], "max": [0.16, 0.06, 0.04] } } ],
  "listeners": [ { "name": "above", "position": [0.08, 0.4, 0.02] } ]
})";

// Claim: frame 0's water grid is the solver's grid at the simulation's cell size; φ < 0 at the
// cell centres deep in the initial water and > 0 in the air above it; the faces between cells
// inside the box solid are closed (open fraction 0) and those in the open water fully open; the
// grid's sides are open where the domain is (+y only). Reference: the scene's geometry.
TEST(FrameWaterGrids, BoxSolidClosesItsFacesAndTheLiquidIsNegative) {
  const TempFolder folder;
  const fs::path scenePath = folder.path() / "box.scene.json", out = folder.path() / "out";
  { std::ofstream(scenePath) << kBoxScene; }
  const CommandOutcome simulate =
      runFluidsound({"simulate", scenePath.string(), "-o", out.string(), "--quiet"});
  ASSERT_EQ(simulate.exitCode, 0) << simulate.err;
  const sim::Scene scene = io::readScene(scenePath);

  const double cell = tools::simulatedCellSize(scene, out, 0);
  EXPECT_DOUBLE_EQ(cell, 0.02);
  const tools::FrameFolderWaterGrids frames(scene, out, cell);
  const acoustics::WaterGrid water = frames.open(0);
  ASSERT_EQ(water.cells, (std::array<int, 3>{8, 6, 2}));
  EXPECT_DOUBLE_EQ(water.cellSize, 0.02);
  ASSERT_EQ(water.phi.size(), water.cellCount());
  // Cells (0 … 1, 1 … 2, k): centres at x = 1, 3 cm, y = 3, 5 cm, inside the water (0 … 6 cm by
  // 0 … 8 cm). Not the floor row: at frame 0 the particles' surface (spheres of half a voxel,
  // smoothed) leaves the cell centres on the floor just outside it (φ ≈ +2.5 mm at 2 cm cells).
  for (int k = 0; k < 2; ++k)
    for (int j = 1; j < 3; ++j)
      for (int i = 0; i < 2; ++i)
        EXPECT_LT(water.phi[water.cellIndex(i, j, k)], 0.0f) << i << j << k;
  // Cell (1, 5, k): y = 11 cm, air above the water.
  for (int k = 0; k < 2; ++k) EXPECT_GT(water.phi[water.cellIndex(1, 5, k)], 0.0f);
  // x faces at x = 12 and 14 cm between cells of the box (cells i = 5 … 7, j = 0 … 2): closed.
  for (int i = 6; i <= 7; ++i)
    for (int j = 0; j <= 1; ++j)
      for (int k = 0; k < 2; ++k)
        EXPECT_EQ(water.faceOpen[0][water.faceIndex(0, i, j, k)], 0.0f) << i << j << k;
  // y face at y = 2 cm inside the box (cell column i = 6): closed; in the water (i = 1): open.
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(water.faceOpen[1][water.faceIndex(1, 6, 1, k)], 0.0f);
    EXPECT_EQ(water.faceOpen[1][water.faceIndex(1, 1, 1, k)], 1.0f);
    EXPECT_EQ(water.faceOpen[0][water.faceIndex(0, 2, 1, k)], 1.0f);
    // The open volume: none inside the box (cell 6, 1), all of it in the water (cell 1, 1).
    ASSERT_EQ(water.cellOpen.size(), water.cellCount());
    EXPECT_EQ(water.cellOpen[water.cellIndex(6, 1, k)], 0.0f);
    EXPECT_EQ(water.cellOpen[water.cellIndex(1, 1, k)], 1.0f);
  }
  EXPECT_EQ(water.openSides, (std::array<bool, 6>{false, false, false, true, false, false}));
}

// Claim: a voxel size that does not divide the domain is bad input naming the frame file, by the
// rules of domain.cell (the frames of another scene's simulation).
TEST(FrameWaterGrids, VoxelSizeThatDoesNotDivideTheDomainNamesTheFrame) {
  const TempFolder folder;
  const fs::path scenePath = folder.path() / "box.scene.json", out = folder.path() / "out";
  { std::ofstream(scenePath) << kBoxScene; }
  const CommandOutcome simulate = runFluidsound(
      {"simulate", scenePath.string(), "-o", out.string(), "--quiet", "--cell", "0.01"});
  ASSERT_EQ(simulate.exitCode, 0) << simulate.err;
  sim::Scene scene = io::readScene(scenePath);
  EXPECT_DOUBLE_EQ(tools::simulatedCellSize(scene, out, 0), 0.01)
      << "--cell's size, not the file's";
  scene.domain.max[0] = 0.165;  // 16.5 cells of 1 cm
  try {
    tools::simulatedCellSize(scene, out, 0);
    ADD_FAILURE() << "no InputError";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("frames/0000.vdb: voxel size: expected"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fluidsound::test
