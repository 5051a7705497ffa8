// tests/sim/fluid/velocity_range_test.cpp — the bound on the liquid's velocity around a position that
// lets the entrainment speed test skip particles that cannot pass it.
#include "sim/fluid/velocity_range.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/fluid/particle_transfer.h"

namespace fluidsound::sim {
namespace {

double distance(const Vec3& a, const Vec3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

TEST(VelocityRange, BoundsEverySampleWithinTwoCells) {
  // Claim: for any position x (inside the grid or just outside it), any particle velocity v and any
  // point q within 2 cells of x, |v − u(q)| ≤ maxDifference(x, v), u interpolated as the
  // entrainment test does (interpolateVelocity, indices clamped). Reference: that sample, on a
  // random field over a grid whose sizes are not multiples of the block. Tolerance: 1e-12
  // relative (the interpolation's rounding; the bound is a max over the faces it mixes).
  GridGeometry grid;
  grid.cells = {11, 7, 9};
  grid.cellSize = 0.01;
  grid.origin = {0.1, -0.2, 0.3};
  MacVelocity u(grid);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> speed(-3.0, 3.0), unit(0.0, 1.0);
  for (int a = 0; a < 3; ++a)
    for (float& f : u[a].values()) f = static_cast<float>(speed(random));
  const VelocityRange range(u, grid);
  int tight = 0;
  for (int n = 0; n < 20000; ++n) {
    Vec3 x, v, q;
    for (int a = 0; a < 3; ++a) {
      x[a] = grid.origin[a] + grid.cellSize * (grid.cells[a] * (1.2 * unit(random) - 0.1));
      v[a] = speed(random);
    }
    // A point at up to 2 cells in a random direction.
    Vec3 direction{unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5};
    const double length = std::hypot(direction[0], direction[1], direction[2]);
    const double reach = VelocityRange::reachCells() * grid.cellSize * unit(random);
    for (int a = 0; a < 3; ++a) q[a] = x[a] + reach * direction[a] / length;
    ASSERT_LE(distance(q, x), VelocityRange::reachCells() * grid.cellSize * (1 + 1e-12));
    const double bound = range.maxDifference(x, v);
    const double actual = distance(v, interpolateVelocity(u, grid, q));
    ASSERT_LE(actual, bound * (1 + 1e-12)) << "x " << x[0] << " " << x[1] << " " << x[2];
    tight += actual > 0.5 * bound;
  }
  EXPECT_GT(tight, 100);  // a bound, not a constant far above every sample
}

TEST(VelocityRange, IsExactForUniformFlow) {
  // Claim: where the liquid moves as a whole at U, the bound is |v − U| itself (every sample is U).
  // Reference: |v − U|. Tolerance: float rounding of U (the faces hold floats), 1e-6 relative.
  GridGeometry grid;
  grid.cells = {8, 8, 8};
  grid.cellSize = 0.005;
  MacVelocity u(grid);
  const Vec3 flow{0.3, -1.2, 0.7};
  for (int a = 0; a < 3; ++a) u[a].fill(static_cast<float>(flow[a]));
  const VelocityRange range(u, grid);
  const Vec3 v{-0.5, 0.25, 1.0};
  EXPECT_NEAR(range.maxDifference({0.02, 0.013, 0.031}, v), distance(v, flow), 1e-6 * distance(v, flow));
}

}  // namespace
}  // namespace fluidsound::sim
