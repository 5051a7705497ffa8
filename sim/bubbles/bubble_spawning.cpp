// sim/bubbles/bubble_spawning.cpp — see bubble_spawning.h.
#include "sim/bubbles/bubble_spawning.h"

#include <algorithm>
#include <cmath>

#include "sim/fluid/cell_interpolation.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/random_stream.h"
#include "sim/fluid/random_variates.h"

namespace fluidsound::sim {

namespace {

/// Rejection sampling of a point in the unit ball from the cube [−1, 1]³ accepts with probability
/// π/6 ≈ 0.52; after this many misses (probability 0.48⁶⁴ ≈ 4e−21) the offset is zero instead, so
/// an attempt always uses a bounded number of variates.
constexpr int kMaxBallTries = 64;

/// The seeds bucketed by grid cell (linear cell index, x fastest), for counting the seeds near a
/// position. Seeds outside the grid fall in the nearest boundary cell; counts use exact distances.
class SeedIndex {
 public:
  SeedIndex(std::span<const BubbleSeed> seeds, const GridGeometry& grid) : seeds_(seeds), grid_(grid) {
    entries_.reserve(seeds.size());
    for (std::size_t s = 0; s < seeds.size(); ++s) {
      const Vec3 g = grid.gridFromWorld(seeds[s].position);
      entries_.push_back({key(cell(g[0], 0), cell(g[1], 1), cell(g[2], 2)), s});
    }
    std::sort(entries_.begin(), entries_.end());
  }

  /// Whether at least `count` seeds lie within `radius` [m] of x (stops counting there).
  bool atLeast(const Vec3& x, double radius, int count) const {
    const Vec3 g = grid_.gridFromWorld(x);
    const double r = radius / grid_.cellSize, r2 = radius * radius;
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) lo[a] = cell(g[a] - r, a), hi[a] = cell(g[a] + r, a);
    int found = 0;
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j) {
        const std::uint64_t first = key(lo[0], j, k), last = key(hi[0], j, k);
        auto it = std::lower_bound(entries_.begin(), entries_.end(), Entry{first, 0});
        for (; it != entries_.end() && it->key <= last; ++it) {
          const Vec3& y = seeds_[it->seed].position;
          const double d2 = (y[0] - x[0]) * (y[0] - x[0]) + (y[1] - x[1]) * (y[1] - x[1]) + (y[2] - x[2]) * (y[2] - x[2]);
          if (d2 <= r2 && ++found >= count) return true;
        }
      }
    return false;
  }

 private:
  struct Entry {
    std::uint64_t key;
    std::size_t seed;
    auto operator<=>(const Entry&) const = default;
  };
  int cell(double g, int axis) const {
    const double top = grid_.cells[axis] - 1;
    return static_cast<int>(std::clamp(std::floor(g), 0.0, top));
  }
  std::uint64_t key(int i, int j, int k) const {
    return (static_cast<std::uint64_t>(k) * grid_.cells[1] + j) * grid_.cells[0] + i;
  }

  std::span<const BubbleSeed> seeds_;
  const GridGeometry& grid_;
  std::vector<Entry> entries_;
};

/// A point uniform in the ball of radius `radius` [m] around the origin.
Vec3 ballOffset(RandomStream& random, double radius) {
  for (int attempt = 0; attempt < kMaxBallTries; ++attempt) {
    const Vec3 q{2.0 * random.uniform() - 1.0, 2.0 * random.uniform() - 1.0, 2.0 * random.uniform() - 1.0};
    if (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] <= 1.0) return {radius * q[0], radius * q[1], radius * q[2]};
  }
  return {0.0, 0.0, 0.0};
}

bool insideGrid(const GridGeometry& grid, const Vec3& x) {
  const Vec3 g = grid.gridFromWorld(x);
  for (int a = 0; a < 3; ++a)
    if (!(g[a] >= 0.0 && g[a] <= grid.cells[a])) return false;
  return true;
}

}  // namespace

SpawnCounts& SpawnCounts::operator+=(const SpawnCounts& o) {
  totalPotential += o.totalPotential, meanAttempts += o.meanAttempts;
  attempts += o.attempts, created += o.created;
  rejectedOutside += o.rejectedOutside, rejectedSolid += o.rejectedSolid;
  rejectedAir += o.rejectedAir, rejectedSparse += o.rejectedSparse;
  return *this;
}

SpawnResult spawnBubbles(std::span<const BubbleSeed> seeds, const LiquidState& liquid,
                         const BubbleSizeSampler& sizes, const BubbleSettings& settings,
                         const SpawnStep& step) {
  const double t = step.t, dt = step.dt;
  const std::uint64_t stream = step.stream;
  SpawnResult result;
  SpawnCounts& counts = result.counts;
  std::vector<double> cumulative(seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    counts.totalPotential += seeds[s].potential;  // in seed order: a fixed summation order
    cumulative[s] = counts.totalPotential;
  }
  counts.meanAttempts = settings.rate * counts.totalPotential * dt;
  RandomStream countStream(stream);
  counts.attempts = poissonVariate(counts.meanAttempts, countStream);
  if (counts.attempts == 0 || !(counts.totalPotential > 0.0)) return result;

  const GridGeometry& grid = liquid.grid;
  const double h = grid.cellSize;
  const SeedIndex index(seeds, grid);
  for (std::size_t a = 0; a < counts.attempts; ++a) {
    RandomStream random(cellStream(stream, a + 1));
    const double radius = sizes.radius(random.uniform());
    // The seed whose cumulative potential first exceeds u·Σ: probability ∝ potential.
    const double pick = random.uniform() * counts.totalPotential;
    const std::size_t s = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(), seeds.size() - 1);
    const Vec3 offset = ballOffset(random, settings.jitterCells * h);
    const double birth = t + dt * (1.0 - random.uniform());
    const Vec3 x{seeds[s].position[0] + offset[0], seeds[s].position[1] + offset[1], seeds[s].position[2] + offset[2]};
    if (!insideGrid(grid, x)) {
      ++counts.rejectedOutside;
      continue;
    }
    if (interpolateNodes(liquid.solidNodeDistance, grid, x) < radius) {
      ++counts.rejectedSolid;
      continue;
    }
    const double depth = -interpolateCellCentres(liquid.liquidDistance, grid, x);
    if (!(depth > radius)) {
      ++counts.rejectedAir;
      continue;
    }
    const double neighbourhood = std::max(settings.neighbourhoodCells * h, settings.neighbourhoodRadii * radius);
    if (!index.atLeast(x, neighbourhood, settings.minSeeds)) {
      ++counts.rejectedSparse;
      continue;
    }
    result.bubbles.push_back({radius, birth, x, depth});
    ++counts.created;
  }
  return result;
}

}  // namespace fluidsound::sim
