// Tests of sim/fluid/particle_seeding.h: the node interpolation the seeding, emission and advection use
// to ask whether a position lies inside a solid.
#include "sim/fluid/particle_seeding.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/cube_grid.h"

namespace fluidsound::sim {
namespace {

// Claim: interpolateNodes clamps a far position to the grid (±inf reads the boundary nodes) and
// turns a NaN coordinate into a NaN distance, never into a read outside the node array (NaN cast
// to int was INT_MIN: a particle emitted at y = 1e308, inf as a float, crashed `run` with SIGSEGV
// once its advected position became NaN).
// Reference: f(x) = x-coordinate of the node [m], so the clamped value is the grid's edge.
// Tolerance: float storage of the node values (1e-7 m).
TEST(ParticleSeeding, NodeInterpolationClampsInfinityAndPropagatesNan) {
  const GridGeometry grid = test::cubeGrid(4, 0.01);
  Array3f nodes(grid.nodeCount(), 0.0f);
  for (int k = 0; k <= 4; ++k)
    for (int j = 0; j <= 4; ++j)
      for (int i = 0; i <= 4; ++i) nodes(i, j, k) = static_cast<float>(0.01 * i);
  EXPECT_NEAR(interpolateNodes(nodes, grid, {0.015, 0.02, 0.02}), 0.015, 1e-7);
  EXPECT_NEAR(interpolateNodes(nodes, grid, {HUGE_VAL, 0.02, 0.02}), 0.04, 1e-7);
  EXPECT_NEAR(interpolateNodes(nodes, grid, {-HUGE_VAL, 0.02, 0.02}), 0.0, 1e-7);
  EXPECT_NEAR(interpolateNodes(nodes, grid, {0.015, 1e308, 0.02}), 0.015, 1e-7);
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 p{0.015, 0.02, 0.02};
    p[axis] = std::nan("");
    EXPECT_TRUE(std::isnan(interpolateNodes(nodes, grid, p))) << "axis " << axis;
  }
}

}  // namespace
}  // namespace fluidsound::sim
