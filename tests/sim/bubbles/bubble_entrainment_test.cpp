// tests/sim/bubbles/bubble_entrainment_test.cpp — entrainment detection: the speed-into-the-liquid test
// and its threshold, no entrainment by liquid moving as a whole, the depth-growth window, seed
// potential decay and lifetime, independence of the particle arrays' order, shortcuts that change
// no decision, unique ids.
#include "sim/bubbles/bubble_entrainment.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/synthetic_tank.h"

namespace fluidsound::sim {
namespace {

using test::SyntheticTank;

constexpr int kCells = 16;
constexpr double kCell = 0.0075;   // h [m]
constexpr double kSurface = 0.06;  // [m]
constexpr std::uint64_t kSeed = 7;

/// Sets every particle's velocity to v and every grid face to `grid`.
void setVelocities(SyntheticTank& tank, const Vec3& v, const Vec3& grid) {
  for (Vec3f& u : tank.velocities()) u = {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
  for (int a = 0; a < 3; ++a) tank.velocity()[a].fill(static_cast<float>(grid[a]));
}

TEST(BubbleEntrainment, SpeedIntoStillLiquidMarksSeedsAboveTheThresholdOnly) {
  // Claim: a surface particle moving into still liquid marks a seed iff its speed along the
  // inward normal reaches entrainmentSpeed (1 m/s): at 1.1 m/s every tagged particle becomes a
  // seed, at 0.9 m/s none does. Reference: the rule in bubble_entrainment.h with φ = y − surface
  // (normal exactly +y). Tolerance: exact counts.
  for (const double speed : {0.9, 1.1}) {
    SyntheticTank tank(kCells, kCell, kSurface, kSeed);
    setVelocities(tank, {0.0, -speed, 0.0}, {0.0, 0.0, 0.0});
    const EntrainmentStep step = detectEntrainment(tank.state(), {}, BubbleSettings{}, 0.0);
    std::cout << "[ measured ] " << speed << " m/s: " << step.taggedParticles << " tagged, " << step.newSeeds
              << " seeds\n";
    ASSERT_GT(step.taggedParticles, 100u);
    EXPECT_EQ(step.newSeeds, speed > 1.0 ? step.taggedParticles : 0u);
    EXPECT_EQ(step.seeds.size(), step.newSeeds);
    for (const BubbleSeed& s : step.seeds) EXPECT_EQ(s.potential, 1.0);
  }
}

TEST(BubbleEntrainment, LiquidMovingAsAWholeDoesNotEntrain) {
  // Claim: a liquid falling or sliding as a whole at 3–5 m/s (particles and grid moving together,
  // as the top of a falling blob or a sloshing surface) marks no seed: the speed test is relative
  // to the liquid beneath. Reference: zero relative velocity. Tolerance: exact (no seed).
  for (const Vec3& v : {Vec3{0.0, -3.0, 0.0}, Vec3{5.0, 0.0, 0.0}, Vec3{2.0, -3.0, 1.0}}) {
    SyntheticTank tank(kCells, kCell, kSurface, kSeed);
    setVelocities(tank, v, v);
    const EntrainmentStep step = detectEntrainment(tank.state(), {}, BubbleSettings{}, 0.0);
    ASSERT_GT(step.taggedParticles, 100u);
    EXPECT_EQ(step.newSeeds, 0u) << "v = (" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  }
}

TEST(BubbleEntrainment, DepthGrowthWithinTheWindowMarksASeed) {
  // Claim: a particle tagged at the surface becomes a seed when its depth grows by at least
  // entrainmentDepthCells·h (2 h) within entrainmentWindow (20 ms), and not when it grows less
  // (1.9 h) or too late (2.5 h after 25 ms). Reference: the rule in bubble_entrainment.h.
  // Tolerance: exact (decisions are ≥ 0.1 h from the threshold, φ is exact).
  SyntheticTank tank(kCells, kCell, kSurface, kSeed, {}, 0);
  const double h = kCell;
  // ids 1, 2, 3 at depth 0.2 h (inside the band): their windows open at t = 0.
  for (int p = 0; p < 3; ++p) tank.add({0.03 + 0.01 * p, kSurface - 0.2 * h, 0.06}, {0.0, 0.0, 0.0});
  const BubbleSettings settings;
  EntrainmentStep step = detectEntrainment(tank.state(), {}, settings, 0.0);
  EXPECT_EQ(step.newSeeds, 0u);
  ASSERT_EQ(step.tags.size(), 3u);
  const double depths[] = {2.3 * h, 2.1 * h, 2.7 * h};  // growth 2.1 h, 1.9 h, 2.5 h
  for (int p = 0; p < 3; ++p) tank.positions()[p][1] = static_cast<float>(kSurface - depths[p]);
  // At 10 ms: particle 0 (2.1 h) becomes a seed; 1 (1.9 h) does not; 2 is checked later.
  auto only = [&](int keep) {
    SyntheticTank one(kCells, kCell, kSurface, kSeed, {}, 0);
    one.add({tank.positions()[keep][0], tank.positions()[keep][1], tank.positions()[keep][2]}, {0.0, 0.0, 0.0});
    one.ids()[0] = tank.ids()[keep];
    return one;
  };
  const SyntheticTank first = only(0), second = only(1), third = only(2);
  const EntrainmentStep a = detectEntrainment(first.state(), step.tags, settings, 0.010);
  const EntrainmentStep b = detectEntrainment(second.state(), step.tags, settings, 0.010);
  const EntrainmentStep c = detectEntrainment(third.state(), step.tags, settings, 0.025);
  EXPECT_EQ(a.newSeeds, 1u);
  EXPECT_EQ(b.newSeeds, 0u);
  EXPECT_EQ(c.newSeeds, 0u);
  EXPECT_EQ(c.tags.size(), 0u) << "a closed window below the band leaves no record";

  // Claim: the seed's potential is e^(−age/τ) and it lives seedLifetime (0.1 s), then is dropped.
  // Reference: e^(−1) at age τ = 30 ms. Tolerance: 1e-15 relative (one exp, one division).
  const double birth = 0.010, tau = settings.potentialDecayTime;
  const EntrainmentStep later = detectEntrainment(first.state(), a.tags, settings, birth + tau);
  ASSERT_EQ(later.seeds.size(), 1u);
  EXPECT_NEAR(later.seeds[0].potential, std::exp(-1.0), 1e-15);
  EXPECT_EQ(later.seeds[0].birth, birth);
  const EntrainmentStep last = detectEntrainment(first.state(), later.tags, settings, birth + 0.1 - 1e-9);
  EXPECT_EQ(last.seeds.size(), 1u);
  const EntrainmentStep gone = detectEntrainment(first.state(), last.tags, settings, birth + 0.1 + 1e-9);
  EXPECT_EQ(gone.seeds.size(), 0u);
}

TEST(BubbleEntrainment, ResultDoesNotDependOnTheOrderOfTheParticleArrays) {
  // Claim: shuffling the particle arrays (as the solver's sort by cell does every substep) changes
  // neither the records nor the seeds. Reference: the unshuffled run. Tolerance: exact equality.
  SyntheticTank tank(kCells, kCell, kSurface, kSeed);
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> speed(-2.5, 0.5);
  for (Vec3f& v : tank.velocities()) v = {0.0f, static_cast<float>(speed(random)), 0.0f};
  const std::size_t n = tank.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), random);
  SyntheticTank shuffled = tank;
  for (std::size_t p = 0; p < n; ++p) {
    shuffled.positions()[p] = tank.positions()[order[p]];
    shuffled.velocities()[p] = tank.velocities()[order[p]];
    shuffled.ids()[p] = tank.ids()[order[p]];
  }
  const BubbleSettings settings;
  const EntrainmentStep a = detectEntrainment(tank.state(), {}, settings, 0.0);
  const EntrainmentStep b = detectEntrainment(shuffled.state(), {}, settings, 0.0);
  ASSERT_GT(a.newSeeds, 10u);
  EXPECT_TRUE(std::ranges::equal(a.tags.tags(), b.tags.tags()));
  EXPECT_TRUE(a.seeds == b.seeds);
}

TEST(BubbleEntrainment, ShortcutsForManyParticlesChangeNoDecision) {
  // Claim: the whole-grid "beyond the band" table (built only with at least one particle per 8
  // cells) and the velocity range are shortcuts: the tank's near-surface particles in a small patch
  // get the same records and seeds alone (fewer than one particle per 8 cells: no table) as among
  // all the tank's particles (8 per cell: table built), and the same with or without a
  // VelocityRange. Reference: the patch alone, without a range. Tolerance: exact equality.
  SyntheticTank tank(kCells, kCell, kSurface, kSeed);
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> speed(-2.5, 0.5);
  for (Vec3f& v : tank.velocities()) v = {0.0f, static_cast<float>(speed(random)), 0.0f};
  SyntheticTank patch = tank;
  patch.positions().clear(), patch.velocities().clear(), patch.ids().clear();
  for (std::size_t p = 0; p < tank.size(); ++p) {
    const Vec3f& x = tank.positions()[p];
    if (x[1] > kSurface - 1.5 * kCell && x[0] > 4 * kCell && x[0] < 9 * kCell && x[2] > 4 * kCell &&
        x[2] < 9 * kCell) {
      patch.positions().push_back(x), patch.velocities().push_back(tank.velocities()[p]);
      patch.ids().push_back(tank.ids()[p]);
    }
  }
  const std::size_t cells = static_cast<std::size_t>(kCells) * kCells * kCells;
  std::cout << "[ measured ] " << tank.size() << " particles in all, " << patch.size()
            << " in the patch, " << cells << " cells\n";
  ASSERT_GE(tank.size() * 8, cells);
  ASSERT_LT(patch.size() * 8, cells);
  const BubbleSettings settings;
  const EntrainmentStep alone = detectEntrainment(patch.state(), {}, settings, 0.0, nullptr);
  const EntrainmentStep aloneWithRange = detectEntrainment(patch.state(), {}, settings, 0.0);
  const EntrainmentStep all = detectEntrainment(tank.state(), {}, settings, 0.0);
  ASSERT_GT(alone.newSeeds, 10u);
  EXPECT_TRUE(std::ranges::equal(alone.tags.tags(), aloneWithRange.tags.tags()));
  EXPECT_TRUE(alone.seeds == aloneWithRange.seeds);
  // The patch's own records and seeds among all of the tank's.
  std::vector<std::uint64_t> ids = patch.ids();
  std::ranges::sort(ids);
  const auto inPatch = [&](std::uint64_t id) { return std::ranges::binary_search(ids, id); };
  std::vector<EntrainmentTag> tags;
  for (const EntrainmentTag& t : all.tags.tags())
    if (inPatch(t.particleId)) tags.push_back(t);
  std::vector<BubbleSeed> seeds;
  for (const BubbleSeed& s : all.seeds)
    if (inPatch(s.particleId)) seeds.push_back(s);
  EXPECT_TRUE(std::ranges::equal(alone.tags.tags(), tags));
  EXPECT_TRUE(alone.seeds == seeds);
}

TEST(BubbleEntrainment, RecordsAreFoundWhateverTheIds) {
  // Claim: the record table finds every record and nothing else, sorted by id, both for ids as
  // the solver numbers them (dense from 0: a slot per id) and for ids far apart (binary search
  // behind a filter). Reference: the ids put in. Tolerance: exact.
  for (const std::uint64_t offset : {std::uint64_t{0}, std::uint64_t{1} << 40}) {
    std::vector<EntrainmentTag> tags;
    for (const std::uint64_t id : {17u, 3u, 900u, 4u}) tags.push_back({offset + id, 0.5, 0.001 * id, kNever});
    const EntrainmentTagTable table(tags);
    ASSERT_EQ(table.size(), 4u);
    EXPECT_TRUE(std::ranges::is_sorted(table.tags(), {}, &EntrainmentTag::particleId));
    for (const EntrainmentTag& t : tags) {
      const EntrainmentTag* found = table.find(t.particleId);
      ASSERT_NE(found, nullptr) << t.particleId;
      EXPECT_EQ(*found, t);
    }
    for (const std::uint64_t id : {0u, 5u, 18u, 899u, 901u, 100000u}) EXPECT_EQ(table.find(offset + id), nullptr) << id;
  }
}

TEST(BubbleEntrainment, DuplicateParticleIdsAreRefused) {
  // Claim: two tagged particles with one id (a solver bug that would merge their records) fail
  // with std::invalid_argument naming particleIds.
  SyntheticTank tank(kCells, kCell, kSurface, kSeed);
  std::fill(tank.ids().begin(), tank.ids().end(), 42);
  try {
    detectEntrainment(tank.state(), {}, BubbleSettings{}, 0.0);
    ADD_FAILURE() << "accepted duplicate ids";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("particleIds must be unique"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fluidsound::sim
