// tests/sim/import/particle_matching_test.cpp — ids for a cache without them
// (sim/particle_matching.h).
#include "sim/particle_matching.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace fluidsound::sim {
namespace {

/// A 10³ cell grid of 1 cm with the velocity (0.3, −0.2, 0.1) m/s on every face.
struct UniformFlow {
  GridGeometry grid{{10, 10, 10}, 0.01, {0.0, 0.0, 0.0}};
  MacVelocity velocity{grid};
  Vec3 u{0.3, -0.2, 0.1};
  UniformFlow() {
    for (int a = 0; a < 3; ++a) velocity[a].fill(static_cast<float>(u[a]));
  }
};

// Reference: in a uniform flow the midpoint rule is exact, x + u·dt (float rounding, 1e-7 m).
TEST(ParticleMatching, AdvectionInAUniformFlowIsExact) {
  const UniformFlow f;
  const std::vector<Vec3f> from{{0.02f, 0.05f, 0.03f}, {0.07f, 0.06f, 0.04f}};
  const double dt = 1.0 / 30.0;
  const std::vector<Vec3f> to = carriedPositions(from, f.velocity, f.velocity, f.grid, dt);
  for (std::size_t p = 0; p < from.size(); ++p)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(to[p][c], from[p][c] + f.u[c] * dt, 1e-7);
}

// 125 particles 2 mm apart carried one frame (1.25 cm, six spacings, more than a cell), then
// shuffled: each finds its own id again; a particle that was not there before gets a new one.
TEST(ParticleMatching, ShuffledParticlesOfTheNextFrameFindTheirIds) {
  const UniformFlow f;
  const double dt = 1.0 / 30.0;
  std::vector<Vec3f> before;
  std::vector<std::uint64_t> ids;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k) {
        before.push_back({0.03f + 0.002f * i, 0.05f + 0.002f * j, 0.03f + 0.002f * k});
        ids.push_back(1000 + 7 * before.size());
      }
  std::vector<std::size_t> order(before.size());
  std::iota(order.begin(), order.end(), 0);
  std::reverse(order.begin(), order.end());
  std::rotate(order.begin(), order.begin() + 40, order.end());
  std::vector<Vec3f> after;
  for (std::size_t p : order)
    after.push_back({static_cast<float>(before[p][0] + f.u[0] * dt), static_cast<float>(before[p][1] + f.u[1] * dt),
                     static_cast<float>(before[p][2] + f.u[2] * dt)});
  after.push_back({0.09f, 0.01f, 0.09f});  // emitted since the frame before
  const std::vector<Vec3f> predicted = carriedPositions(before, f.velocity, f.velocity, f.grid, dt);
  std::uint64_t nextId = 5000;
  const std::vector<std::uint64_t> found = matchParticleIds(predicted, ids, after, f.grid.cellSize, nextId);
  ASSERT_EQ(found.size(), after.size());
  for (std::size_t q = 0; q < order.size(); ++q) EXPECT_EQ(found[q], ids[order[q]]) << q;
  EXPECT_EQ(found.back(), 5000u);
  EXPECT_EQ(nextId, 5001u);
}

// Two particles of the next frame in reach of one predicted place: the nearer takes its id, the
// other a new one — no id twice.
TEST(ParticleMatching, NoIdIsGivenTwice) {
  const std::vector<Vec3f> predicted{{0.05f, 0.05f, 0.05f}};
  const std::vector<std::uint64_t> ids{42};
  const std::vector<Vec3f> next{{0.053f, 0.05f, 0.05f}, {0.051f, 0.05f, 0.05f}};
  std::uint64_t nextId = 43;
  const std::vector<std::uint64_t> found = matchParticleIds(predicted, ids, next, 0.01, nextId);
  EXPECT_EQ(found[1], 42u);
  EXPECT_EQ(found[0], 43u);
}

}  // namespace
}  // namespace fluidsound::sim
