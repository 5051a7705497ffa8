// Tests of io/frame_surface.h: a frame file's level set read back and sampled, and the free surface
// above a bubble it gives (acoustics/transfer/level_set_surface.h).
#include "io/frame_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include "acoustics/transfer/level_set_surface.h"
#include "io/frame_files.h"
#include "io/input_error.h"
#include "sim/fluid/fluid_solver.h"
#include "sim/scene.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

constexpr double kCell = 0.01;  // [m]

/// frames/0000.vdb of a resting layer 4 cm deep in a 10 cm closed box, 1 cm cells.
std::filesystem::path layerFrame(const test::TempFolder& folder) {
  sim::Scene s;
  s.domain.max = {0.1, 0.1, 0.1};
  s.domain.cell = kCell;
  s.time.duration = 1.0;
  s.liquid.push_back({sim::Box{{0, 0, 0}, {0.1, 0.04, 0.1}}, {}});
  const sim::FluidSolver solver(s);
  std::filesystem::create_directories(folder.path() / "frames");
  const auto path = folder.path() / "frames" / "0000.vdb";
  writeFrameVdb(path, solver.grid(), solver.particles(), solver.velocity(), {solver.particleRadius()});
  return path;
}

// Claim: under a flat surface the local plane is that surface: normal up (the level set's
// gradient), the bubble's depth that of the surface above it, and the plane passes at that depth
// above the centre (as the image-source model requires). Reference: the layer's top, y = 4 cm.
// Tolerance: 0.05 h on the depth (the frame's surface is calibrated to a seeded layer's top,
// io/frame_vdb.cpp: measured 0.01 h low), 0.05 on the normal's components.
TEST(FrameLevelSet, FlatLayerGivesAnUpwardPlaneAtTheSurface) {
  test::TempFolder folder;
  layerFrame(folder);
  const FrameFolderLevelSets levelSets(folder.path());
  const acoustics::LevelSetFrameSurfaces frames(levelSets);
  const std::unique_ptr<acoustics::FrameSurface> surface = frames.open(0);
  for (const double y : {0.015, 0.025, 0.034}) {
    const Vec3 centre{0.05, y, 0.05};
    // The track's depth may be off (the simulation's surface differs a little): start 2 mm wrong.
    const acoustics::LocalSurface s =
        surface->surfaceAbove(centre, 0.04 - y + 0.002, {0.0, 1.0, 0.0});
    EXPECT_NEAR(s.normal[1], 1.0, 0.05);
    EXPECT_NEAR(s.normal[0], 0.0, 0.05);
    EXPECT_NEAR(s.depth, 0.04 - y, 0.05 * kCell) << "y = " << y;
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(s.point[a], centre[a] + s.depth * s.normal[a], 1e-12);
  }
}

// Claim: the level set read back is the layer's: φ ≈ y − 4 cm within half a cell of the surface
// (farther out the particle surface's level set is no exact distance: 0.15 h off at 1.5 h),
// negative in the liquid, and its band and voxel are the frame's. Reference: the layer's top.
// Tolerance: 0.05 h (the frame's surface sits 0.01 h low, io/frame_vdb.cpp).
TEST(FrameLevelSet, SamplesTheLayersDistance) {
  test::TempFolder folder;
  const FrameLevelSet level(layerFrame(folder));
  EXPECT_DOUBLE_EQ(level.voxelSize(), kCell);
  EXPECT_GE(level.bandHalfWidth(), 2.0 * kCell);
  for (const double y : {0.035, 0.04, 0.045})
    EXPECT_NEAR(level.phi({0.05, y, 0.05}), y - 0.04, 0.05 * kCell) << "y = " << y;
}

// Claim: where the point above the bubble is beyond the narrow band, the plane is the horizontal
// one at the track's depth (no gradient to read). Reference: the inputs. Tolerance: exact.
TEST(FrameLevelSet, BeyondTheBandFallsBackToTheHorizontalPlane) {
  test::TempFolder folder;
  const FrameLevelSet level(layerFrame(folder));
  const acoustics::LocalSurface s =
      acoustics::localSurfacePlane(level, {0.05, 0.01, 0.05}, 0.08, {0.0, 1.0, 0.0});
  EXPECT_EQ(s.normal, (Vec3{0.0, 1.0, 0.0}));
  EXPECT_DOUBLE_EQ(s.depth, 0.08);
  EXPECT_DOUBLE_EQ(s.point[1], 0.09);
}

// Bad input: a missing frame file is an InputError naming it.
TEST(FrameLevelSet, MissingFrameNamesTheFile) {
  test::TempFolder folder;
  EXPECT_THROW(FrameLevelSet(folder.path() / "0007.vdb"), InputError);
}

// Bad input: a frame whose compressed block declares 86 GB (found by tests/fuzz/frame_vdb_fuzz;
// OpenVDB allocates the declared size before reading it) is a one-line InputError naming the
// file, not std::bad_alloc (exit 5 from transfer). Truncated frames and damage to each header byte:
// VdbFileCheck.TruncatedOrDamagedFrameIsAnInputError.
TEST(FrameLevelSet, CorruptBlockSizeIsAnInputError) {
  const std::filesystem::path frame =
      std::filesystem::path(FLUIDSOUND_SOURCE_DIR) / "tests/fuzz/corpus/frame_vdb/blosc_block_size_86gb.vdb";
  try {
    const FrameLevelSet level(frame);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), frame.string());
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace fluidsound::io
