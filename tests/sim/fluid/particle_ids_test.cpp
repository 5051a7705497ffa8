// tests/sim/fluid/particle_ids_test.cpp — numbering new particles: unassigned ids get consecutive
// numbers in array order, assigned ones are kept, and the counter advances past them.
#include "sim/fluid/particle_ids.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace fluidsound::sim {
namespace {

TEST(ParticleIds, NewParticlesAreNumberedInArrayOrderAndOldOnesKeepTheirIds) {
  // Claim: assignParticleIds gives the unassigned entries next, next + 1, … in array order,
  // leaves assigned ids alone and returns how many it numbered. Reference: the rule. Exact.
  constexpr std::uint64_t u = kUnassignedParticleId;
  std::vector<std::uint64_t> ids{7, u, 3, u, u};
  std::uint64_t next = 10;
  EXPECT_EQ(assignParticleIds(ids, next), 3u);
  EXPECT_EQ(ids, (std::vector<std::uint64_t>{7, 10, 3, 11, 12}));
  EXPECT_EQ(next, 13u);
  EXPECT_EQ(assignParticleIds(ids, next), 0u);
  EXPECT_EQ(next, 13u);
}

}  // namespace
}  // namespace fluidsound::sim
