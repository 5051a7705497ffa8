// tests/acoustics/transfer/water_modes_test.cpp — a frame's water modes (water_modes.h): the
// Lanczos route finds what the dense eigensolver finds, degenerate pairs included, and a box of
// water resonates at its quarter waves (issue 19; shared transfer.md §2–3).
#include "acoustics/transfer/water_modes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "acoustics/transfer/water_helmholtz.h"
#include "tests/support/water_grid_shapes.h"

namespace fluidsound::acoustics {
namespace {

constexpr double kWaterSoundSpeed = 1482.0;  // c_w [m/s], physics.md §2

// Reference: Eigen's dense SelfAdjointEigenSolver on the same M^{-1/2} L M^{-1/2}. A square
// 4 × 4 cm box of water 4 cm deep has exactly degenerate pairs (x ↔ z), which a single-vector
// Lanczos can miss; every eigenvalue below the cut must be found, each as often as the dense
// solver finds it. Tolerance 1e-9 relative: Lanczos converged to 1e-12, dense to rounding.
TEST(WaterModes, LanczosFindsEveryModeTheDenseSolverFinds) {
  const WaterHelmholtz water(test::waterBox({0.04, 0.04, 0.04, 0.005, 2}), kWaterSoundSpeed, 0.0);
  ASSERT_EQ(water.unknowns(), 512u);
  const double cut = std::pow(2.0 * std::numbers::pi * 40000.0 / kWaterSoundSpeed, 2);
  const WaterModes dense = lowestWaterModesDense(water, cut);
  const WaterModes lanczos = lowestWaterModes(water, cut, 160);
  ASSERT_GE(dense.eigenvalue.size(), 10);
  EXPECT_TRUE(lanczos.complete);
  ASSERT_EQ(lanczos.eigenvalue.size(), dense.eigenvalue.size());
  for (Eigen::Index j = 0; j < dense.eigenvalue.size(); ++j)
    EXPECT_NEAR(lanczos.eigenvalue[j] / dense.eigenvalue[j], 1.0, 1e-9) << "mode " << j;
  const Eigen::MatrixXd gram =
      lanczos.shape.transpose() * water.mass().asDiagonal() * lanczos.shape;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).norm(), 1e-9);
  const Eigen::MatrixXd residual =
      Eigen::MatrixXd(water.stiffness()) * lanczos.shape -
      water.mass().asDiagonal() * lanczos.shape * lanczos.eigenvalue.asDiagonal();
  EXPECT_LT(residual.norm() / (Eigen::MatrixXd(water.stiffness()) * lanczos.shape).norm(), 1e-9);
}

// Reference: a rigid box of water (floor and walls rigid, surface pressure-release) resonates at
// k² = ((2m+1)π/(2H))² + (pπ/L_x)² + (qπ/L_z)² (shared transfer.md §3: c_w/(4H) the first). The
// 7-point operator's eigenvalues sit (kh)²/12 low: at 5 mm cells and 6 cm depth, 0.2 % for the
// quarter wave, 1 % allowed for the three lowest.
TEST(WaterModes, BoxOfWaterResonatesAtItsQuarterWaves) {
  const double width = 0.1, depth = 0.06, length = 0.02;
  const WaterHelmholtz water(test::waterBox({width, depth, length, 0.005, 2}), kWaterSoundSpeed,
                             0.0);
  const double quarter = std::pow(std::numbers::pi / (2.0 * depth), 2);
  const WaterModes modes = lowestWaterModes(water, 8.0 * quarter, 160);
  ASSERT_TRUE(modes.complete);
  const std::vector<double> expected{quarter, quarter + std::pow(std::numbers::pi / width, 2),
                                     quarter + std::pow(2.0 * std::numbers::pi / width, 2)};
  ASSERT_GE(modes.eigenvalue.size(), 3);
  for (std::size_t j = 0; j < expected.size(); ++j)
    EXPECT_NEAR(modes.eigenvalue[j] / expected[j], 1.0, 0.01) << "mode " << j;
  const double firstHz = std::sqrt(modes.eigenvalue[0]) * kWaterSoundSpeed / (2 * std::numbers::pi);
  EXPECT_NEAR(firstHz / (kWaterSoundSpeed / (4.0 * depth)), 1.0, 0.01);
}

TEST(WaterModes, TooManyModesBelowTheCutAreMarkedIncomplete) {
  const WaterHelmholtz water(test::waterBox({0.04, 0.04, 0.04, 0.005, 2}), kWaterSoundSpeed, 0.0);
  const double cut = std::pow(2.0 * std::numbers::pi * 60000.0 / kWaterSoundSpeed, 2);
  const WaterModes modes = lowestWaterModes(water, cut, 8);
  EXPECT_FALSE(modes.complete);
  EXPECT_LE(modes.eigenvalue.size(), 8);
}

}  // namespace
}  // namespace fluidsound::acoustics
