// tests/sim/bubbles/bubble_spawning_test.cpp — creation attempts: their number is Poisson with mean
// rate·Σpotential·dt, positions follow the seeds in proportion to their potential, radii follow
// the size distribution, and an isolated seed makes no bubble.
#include "sim/bubbles/bubble_spawning.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "sim/fluid/random_stream.h"
#include "support/synthetic_tank.h"

namespace fluidsound::sim {
namespace {

using test::SyntheticTank;

constexpr int kCells = 24;
constexpr double kCell = 0.005;    // h [m]
constexpr double kSurface = 0.10;  // [m]
constexpr std::uint64_t kSeed = 11;

/// `count` seeds of potential `potential` on a small lattice (spacing h/2) around `centre`.
std::vector<BubbleSeed> cluster(const Vec3& centre, int count, double potential, std::uint64_t firstId) {
  std::vector<BubbleSeed> seeds;
  for (int n = 0; n < count; ++n) {
    const Vec3 offset{0.5 * kCell * (n % 3 - 1), 0.5 * kCell * ((n / 3) % 3 - 1), 0.5 * kCell * ((n / 9) % 3 - 1)};
    seeds.push_back({firstId + n, {centre[0] + offset[0], centre[1] + offset[1], centre[2] + offset[2]}, 0.0, potential});
  }
  return seeds;
}

TEST(BubbleSpawning, AttemptCountIsPoissonWithTheStatedMean) {
  // Claim: the number of attempts per step is Poisson with mean rate·Σpotential·dt (here
  // 20/s · 13.5 · 0.01 s = 2.7). Reference: a Poisson law has mean = variance = 2.7. Tolerance,
  // over N = 4000 steps: 4 standard errors, 4√(μ/N) on the mean and 4√((μ + 2μ²)/N) on the
  // variance (the standard error of a Poisson sample variance).
  const SyntheticTank tank(kCells, kCell, kSurface, kSeed, {}, 0);
  const std::vector<BubbleSeed> seeds = cluster({0.06, 0.05, 0.06}, 27, 0.5, 0);
  const BubbleSizeSampler sizes{PowerLawBubbleSizes{}};
  const BubbleSettings settings;
  const double dt = 0.01, mu = settings.rate * 13.5 * dt;
  const int n = 4000;
  double sum = 0.0, sum2 = 0.0;
  for (int s = 0; s < n; ++s) {
    const SpawnResult r = spawnBubbles(seeds, tank.state(), sizes, settings, {0.0, dt, cellStream(kSeed, s)});
    ASSERT_DOUBLE_EQ(r.counts.meanAttempts, mu);
    sum += r.counts.attempts;
    sum2 += static_cast<double>(r.counts.attempts) * r.counts.attempts;
  }
  const double mean = sum / n, variance = (sum2 - n * mean * mean) / (n - 1);
  std::cout << "[ measured ] attempts: mean " << mean << ", variance " << variance << " (Poisson " << mu << ")\n";
  EXPECT_NEAR(mean, mu, 4.0 * std::sqrt(mu / n));
  EXPECT_NEAR(variance, mu, 4.0 * std::sqrt((mu + 2.0 * mu * mu) / n));
}

TEST(BubbleSpawning, PositionsFollowTheSeedsInProportionToTheirPotential) {
  // Claim: density sampling picks seeds with probability ∝ potential: with two clusters of equal
  // size, potentials 1 and 0.25, 80 % of the bubbles are born at the first. Tolerance: 4 binomial
  // standard errors, 4√(p(1 − p)/n). All positions lie within jitter (½ h) of a seed.
  const SyntheticTank tank(kCells, kCell, kSurface, kSeed, {}, 0);
  const Vec3 a{0.04, 0.05, 0.06}, b{0.08, 0.05, 0.06};
  std::vector<BubbleSeed> seeds = cluster(a, 27, 1.0, 0);
  const std::vector<BubbleSeed> second = cluster(b, 27, 0.25, 100);
  seeds.insert(seeds.end(), second.begin(), second.end());
  const BubbleSizeSampler sizes{PowerLawBubbleSizes{}};
  BubbleSettings settings;
  settings.rate = 1e4;
  std::size_t atA = 0, total = 0;
  for (int s = 0; s < 20; ++s) {
    const SpawnResult r = spawnBubbles(seeds, tank.state(), sizes, settings, {0.0, 0.01, cellStream(kSeed, s)});
    for (const SpawnedBubble& bubble : r.bubbles) {
      const double da = std::hypot(bubble.position[0] - a[0], bubble.position[1] - a[1], bubble.position[2] - a[2]);
      const double db = std::hypot(bubble.position[0] - b[0], bubble.position[1] - b[1], bubble.position[2] - b[2]);
      EXPECT_LE(std::min(da, db), std::sqrt(3.0) * 0.5 * kCell + 0.5 * kCell + 1e-12);
      atA += da < db;
      ++total;
    }
  }
  const double p = 0.8, fraction = static_cast<double>(atA) / total;
  std::cout << "[ measured ] " << total << " bubbles, " << 100.0 * fraction << " % at the stronger cluster\n";
  ASSERT_GT(total, 10000u);
  EXPECT_NEAR(fraction, p, 4.0 * std::sqrt(p * (1.0 - p) / total));
}

TEST(BubbleSpawning, AcceptedRadiiFollowTheSizeDistribution) {
  // Claim: where no test rejects (deep, dense seeds), the accepted radii follow the size
  // distribution. Reference: BubbleSizeSampler::cumulativeFraction (Deane & Stokes power law).
  // Tolerance: Kolmogorov–Smirnov D < 1.949/√n, the 0.1 % critical value.
  const SyntheticTank tank(kCells, kCell, kSurface, kSeed, {}, 0);
  std::vector<BubbleSeed> seeds;
  for (int c = 0; c < 8; ++c) {  // a 2×2×2 block of clusters, 2 cm apart, 3–5 cm deep
    const std::vector<BubbleSeed> part =
        cluster({0.05 + 0.02 * (c & 1), 0.05 + 0.02 * ((c >> 1) & 1), 0.05 + 0.02 * (c >> 2)}, 27, 1.0, 100 * c);
    seeds.insert(seeds.end(), part.begin(), part.end());
  }
  const BubbleSizeSampler sizes{PowerLawBubbleSizes{}};
  BubbleSettings settings;
  settings.rate = 2e3;
  std::vector<double> radii;
  for (int s = 0; s < 5; ++s) {
    const SpawnResult r = spawnBubbles(seeds, tank.state(), sizes, settings, {0.0, 0.01, cellStream(kSeed, s)});
    EXPECT_EQ(r.counts.created, r.counts.attempts);
    for (const SpawnedBubble& b : r.bubbles) radii.push_back(b.radius);
  }
  std::sort(radii.begin(), radii.end());
  const std::size_t n = radii.size();
  ASSERT_GT(n, 1000u);
  double d = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double f = sizes.cumulativeFraction(radii[i]);
    d = std::max({d, (i + 1.0) / n - f, f - static_cast<double>(i) / n});
  }
  std::cout << "[ measured ] " << n << " radii: KS D = " << d << " (critical " << 1.949 / std::sqrt(n) << ")\n";
  EXPECT_LT(d, 1.949 / std::sqrt(static_cast<double>(n)));
}

TEST(BubbleSpawning, AnIsolatedSeedMakesNoBubble) {
  // Claim: with minSeeds = 3, one seed alone makes no bubble (every attempt is rejected as
  // sparse), and two more seeds within a cell of it let bubbles form. Reference: the rule
  // "≥ minSeeds seeds within max(1 h, 4 r)". Tolerance: exact counts.
  const SyntheticTank tank(kCells, kCell, kSurface, kSeed, {}, 0);
  BubbleSettings settings;
  settings.rate = 1e4;
  const BubbleSizeSampler sizes{PowerLawBubbleSizes{}};
  std::vector<BubbleSeed> seeds{{1, {0.06, 0.05, 0.06}, 0.0, 1.0}};
  const SpawnResult alone = spawnBubbles(seeds, tank.state(), sizes, settings, {0.0, 0.01, kSeed});
  ASSERT_GT(alone.counts.attempts, 20u);
  EXPECT_EQ(alone.counts.created, 0u);
  EXPECT_EQ(alone.counts.rejectedSparse, alone.counts.attempts);
  seeds.push_back({2, {0.06 + 0.4 * kCell, 0.05, 0.06}, 0.0, 0.0});  // potential 0: counted, never chosen
  seeds.push_back({3, {0.06, 0.05 - 0.4 * kCell, 0.06}, 0.0, 0.0});
  const SpawnResult three = spawnBubbles(seeds, tank.state(), sizes, settings, {0.0, 0.01, kSeed});
  std::cout << "[ measured ] alone: " << alone.counts.created << " of " << alone.counts.attempts
            << "; with two neighbours: " << three.counts.created << " of " << three.counts.attempts << "\n";
  EXPECT_GT(three.counts.created, three.counts.attempts / 4);
}

}  // namespace
}  // namespace fluidsound::sim
