// tests/sim/frame_volume_test.cpp — report.json's liquid_volume counts the liquid outside the
// scene solids in every frame, frame 0 (the initial state, no substep run) included: a tank
// with a solid hemisphere on its floor reads its water's closed-form volume from the start.
// (Frame 0 used to count the liquid inside the solid: the tank of the issue read 451 cm³ at
// frame 0 and 442.7 cm³ from frame 1 on; this one 450.7 and 444.2 cm³, so the test fails on
// that code.) Runs the real `fluidsound simulate`.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "support/command_runner.h"
#include "support/temp_folder.h"

namespace fluidsound::sim {
namespace {

constexpr double kSide = 0.1;     // tank width and depth [m]
constexpr double kDepth = 0.05;   // water depth [m]
constexpr double kRadius = 0.03;  // hemisphere on the floor [m]

void writeTankScene(const std::filesystem::path& file) {
  std::ofstream(file) << R"({
  "format": "fluidsound.scene/1",
  "domain": { "min": [0, 0, 0], "max": [0.1, 0.1, 0.1], "cell": 0.005 },
  "time": { "duration": 0.1, "fps": 30 },
  "liquid": [ { "box": { "min": [0, 0, 0], "max": [0.1, 0.05, 0.1] } } ],
  "solids": [ { "sphere": { "center": [0.05, 0, 0.05], "radius": 0.03 } } ],
  "listeners": [ { "name": "above", "position": [0.05, 0.5, 0.05] } ]
})";
}

// Claim: frames 0 and 1 of report.json both hold the water's volume outside the hemisphere.
// Reference: closed form, a box of water minus the half ball it holds,
// 0.1 · 0.1 · 0.05 − (2/3)·π·0.03³ = 443.45 cm³.
// Tolerance: 1 % (4.4 cm³). The volume is φ sampled 4 × 4 × 4 per cell near the surface or a
// solid, a sample counting as solid by the trilinear nodal distance: the hemisphere's curved
// surface (2π r² = 57 cm²; its disc lies on the floor) is placed to within ~h/16 of a 5 mm cell
// by the samples and ~h/8 by the trilinear distance at its curvature, 57 cm² · 0.06 cm ≈ 3.5 cm³
// at most. Measured: +0.17 % (444.23 cm³) in both frames. Frame 0 must also agree with frame 1
// to 0.5 %: one substep moves water at rest by nothing, and each frame's level set is shifted to
// the start volume.
TEST(FrameVolume, FrameZeroCountsTheLiquidOutsideTheSolidsAsLaterFramesDo) {
  test::TempFolder folder;
  const auto scene = folder.path() / "tank.scene.json";
  writeTankScene(scene);
  const auto out = folder.path() / "out";
  const test::CommandOutcome run = test::runFluidsound(
      {"simulate", scene.string(), "-o", out.string(), "--frames", "0:1", "--quiet"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(out / "report.json"));
  const auto& frames = report.at("results").at("frames");
  ASSERT_GE(frames.size(), 2u);
  const double closedForm =
      kSide * kSide * kDepth - 2.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
  const double frame0 = frames[0].at("liquid_volume"), frame1 = frames[1].at("liquid_volume");
  std::printf(
      "liquid volume: closed form %.2f cm³, frame 0 %.2f cm³ (%+.2f %%), frame 1 %.2f cm³\n",
      closedForm * 1e6, frame0 * 1e6, 100.0 * (frame0 / closedForm - 1.0), frame1 * 1e6);
  EXPECT_NEAR(frame0, closedForm, 0.01 * closedForm);
  EXPECT_NEAR(frame1, closedForm, 0.01 * closedForm);
  EXPECT_NEAR(frame0, frame1, 0.005 * closedForm);
}

}  // namespace
}  // namespace fluidsound::sim
