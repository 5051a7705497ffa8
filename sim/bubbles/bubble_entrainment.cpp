// sim/bubbles/bubble_entrainment.cpp — see bubble_entrainment.h.
#include "sim/bubbles/bubble_entrainment.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "sim/fluid/block_parallel.h"
#include "sim/fluid/cell_interpolation.h"
#include "sim/fluid/particle_transfer.h"
#include "sim/fluid/random_stream.h"
#include "sim/fluid/velocity_range.h"

namespace fluidsound::sim {

namespace {

/// Particles per parallel block: large enough to amortise a task (a block costs tens of µs when
/// its particles are near the surface, about 150 ns each), small enough that a pour of a few
/// thousand particles, all near the surface, spreads evenly over the threads (2 500: 10 blocks).
constexpr std::size_t kBlockParticles = 256;
/// The whole-grid "beyond the band" table (beyondBandStencils, about 2 ns per cell) is built only
/// when there is at least one particle per this many cells: each deep particle it lets skip saves
/// an interpolation (about 15 ns), so with fewer particles (a glass pour: 2 500 particles, nearly
/// all near the surface, in 41 000 cells) the table costs more than it saves. Either way the
/// decisions are the same.
constexpr std::size_t kCellsPerParticleForTable = 8;
/// Filter bits per record: a deep particle passes the filter (and pays a binary search) with
/// probability ≈ 1/kFilterBitsPerTag.
constexpr std::size_t kFilterBitsPerTag = 16;
/// Ids below kDenseIdsPerTag × records + kDenseIdsAlways get a slot each (4 bytes per id): the
/// solver numbers particles 0, 1, 2, … so its ids stay within a few times the particle count, and
/// a seeded tank's first records are a small fraction of its particles.
constexpr std::uint64_t kDenseIdsPerTag = 64;
constexpr std::uint64_t kDenseIdsAlways = std::uint64_t{1} << 20;
/// Below this |∇φ| [-] (φ is a distance, |∇φ| ≈ 1 near the surface) the normal is undefined: the
/// particle sits where φ is flat (e.g. the solver's constant far value), and the speed test is
/// skipped.
constexpr double kMinimumDistanceGradient = 0.1;

/// Particles ahead whose record is fetched into the cache while this one is tested: the records
/// are in id order, the particles in cell order, so each record is a random read that the fluid's
/// substep has pushed out of the caches (about half the loop's own time went to waiting for it).
constexpr std::size_t kPrefetchAhead = 8;

/// Relative margin of the "beyond the band" stencil test: far above the rounding of a trilinear
/// interpolation (a few ulp), far below any distance that matters.
constexpr double kBeyondBandMargin = 1e-9;

/// A speed test is skipped when the bound on the relative speed (velocity_range.h) is below the
/// threshold by this relative margin: the bound and the test round differently, by a few ulp.
constexpr double kSpeedBoundMargin = 1e-6;

std::uint64_t filterSlot(std::uint64_t id) { return cellStream(0, id); }

/// Per cell c, whether all 8 centres of the interpolation stencil based at c (cell_interpolation.h:
/// c and c + 1 per axis, clamped to the grid) hold φ beyond ±band on one side, so that φ anywhere
/// in that stencil is beyond the band: the particle there needs no interpolation. Computed per
/// axis in turn.
std::vector<std::uint8_t> beyondBandStencils(const Array3f& phi, double band) {
  const int ni = phi.ni(), nj = phi.nj(), nk = phi.nk();
  const std::size_t sj = static_cast<std::size_t>(ni), sk = sj * nj, n = sk * nk;
  // The side of each centre: 1 above +band, 2 below −band, 0 inside the band (with a relative
  // margin, so that interpolation rounding cannot bring a value back inside).
  const double beyond = band * (1.0 + kBeyondBandMargin);
  std::vector<std::uint8_t> side(n);
  for (std::size_t at = 0; at < n; ++at)
    side[at] = phi.data()[at] > beyond ? 1 : (phi.data()[at] < -beyond ? 2 : 0);
  // Along x, then y, then z: a cell keeps its side if the next cell along the axis (when there is
  // one) has the same; after three passes, if all 8 corners of its stencil have.
  const auto keepIfSame = [&](std::size_t at, std::size_t next) {
    side[at] = side[next] == side[at] ? side[at] : 0;
  };
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i + 1 < ni; ++i) keepIfSame(k * sk + j * sj + i, k * sk + j * sj + i + 1);
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j + 1 < nj; ++j)
      for (int i = 0; i < ni; ++i) keepIfSame(k * sk + j * sj + i, k * sk + (j + 1) * sj + i);
  for (int k = 0; k + 1 < nk; ++k)
    for (std::size_t at = k * sk; at < (k + 1) * sk; ++at) keepIfSame(at, at + sk);
  return side;
}

/// The base cell of the interpolation stencil at x (as interpolateCellCentres places it).
std::size_t stencilBase(const GridGeometry& grid, const Vec3& x) {
  const Vec3 g = grid.gridFromWorld(x);
  std::size_t at = 0;
  for (int a = 2; a >= 0; --a) {
    const double top = static_cast<double>(grid.cells[a] - 1);
    const double c = std::clamp(g[a] - 0.5, 0.0, top);
    at = at * grid.cells[a] + std::min(static_cast<int>(c), std::max(grid.cells[a] - 2, 0));
  }
  return at;
}

/// The records and seeds one block of particles produced.
struct BlockResult {
  std::vector<EntrainmentTag> tags;
  std::vector<BubbleSeed> seeds;
  std::size_t tagged = 0, newSeeds = 0;
};

/// The speed at which particle velocity v moves into the liquid relative to the liquid
/// probe·h beneath x along the inward normal [m/s], the normal from the gradient of φ at x
/// (`phi`); −∞ where the normal is undefined.
double relativeSpeedIntoLiquid(const LiquidState& liquid, const CellCentreStencil& phi,
                               const Vec3& x, const Vec3& v, double probeDistance) {
  const Vec3 g = phi.gradient();
  const double norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if (!(norm >= kMinimumDistanceGradient)) return -std::numeric_limits<double>::infinity();
  const Vec3 inward{-g[0] / norm, -g[1] / norm, -g[2] / norm};
  const Vec3 probe{x[0] + probeDistance * inward[0], x[1] + probeDistance * inward[1],
                   x[2] + probeDistance * inward[2]};
  const Vec3 beneath = interpolateVelocity(liquid.velocity, liquid.grid, probe);
  double speed = 0.0;
  for (int a = 0; a < 3; ++a) speed += (v[a] - beneath[a]) * inward[a];
  return speed;
}

}  // namespace

EntrainmentTagTable::EntrainmentTagTable(std::vector<EntrainmentTag> tags)
    : tags_(std::move(tags)) {
  if (tags_.empty()) return;
  const auto duplicate = [](std::uint64_t id) {
    std::ostringstream message;
    message << "LiquidState.particleIds must be unique, but id " << id
            << " belongs to two particles";
    throw std::invalid_argument(message.str());
  };
  std::uint64_t largest = 0;
  for (const EntrainmentTag& t : tags_) largest = std::max(largest, t.particleId);
  if (largest < kDenseIdsPerTag * tags_.size() + kDenseIdsAlways) {
    // Ids as the solver numbers them (0, 1, 2, … in order of creation): a slot per id, which also
    // puts the records in id order without a comparison sort.
    slotOfId_.assign(largest + 1, kNoSlot);
    for (std::size_t r = 0; r < tags_.size(); ++r) {
      std::uint32_t& slot = slotOfId_[tags_[r].particleId];
      if (slot != kNoSlot) duplicate(tags_[r].particleId);
      slot = static_cast<std::uint32_t>(r);
    }
    std::vector<EntrainmentTag> sorted;
    sorted.reserve(tags_.size());
    for (std::uint32_t& slot : slotOfId_)
      if (slot != kNoSlot) {
        sorted.push_back(tags_[slot]);
        slot = static_cast<std::uint32_t>(sorted.size() - 1);
      }
    tags_ = std::move(sorted);
    return;
  }
  std::sort(tags_.begin(), tags_.end(), [](const EntrainmentTag& a, const EntrainmentTag& b) {
    return a.particleId < b.particleId;
  });
  for (std::size_t i = 1; i < tags_.size(); ++i)
    if (tags_[i].particleId == tags_[i - 1].particleId) duplicate(tags_[i].particleId);
  const std::uint64_t bits =
      std::bit_ceil(std::max<std::uint64_t>(64, kFilterBitsPerTag * tags_.size()));
  mask_ = bits - 1;
  filter_.assign(bits / 64, 0);
  for (const EntrainmentTag& t : tags_) {
    const std::uint64_t slot = filterSlot(t.particleId) & mask_;
    filter_[slot >> 6] |= std::uint64_t{1} << (slot & 63);
  }
}

const EntrainmentTag* EntrainmentTagTable::find(std::uint64_t id) const {
  if (!slotOfId_.empty()) {
    if (id >= slotOfId_.size() || slotOfId_[id] == kNoSlot) return nullptr;
    return &tags_[slotOfId_[id]];
  }
  if (tags_.empty()) return nullptr;
  const std::uint64_t slot = filterSlot(id) & mask_;
  if (!((filter_[slot >> 6] >> (slot & 63)) & 1)) return nullptr;
  const auto it = std::lower_bound(
      tags_.begin(), tags_.end(), id,
      [](const EntrainmentTag& t, std::uint64_t key) { return t.particleId < key; });
  return it != tags_.end() && it->particleId == id ? &*it : nullptr;
}

bool entrainmentUsesVelocityRange(const BubbleSettings& settings) {
  return std::isfinite(settings.entrainmentSpeed) &&
         settings.probeCells <= VelocityRange::reachCells();
}

EntrainmentStep detectEntrainment(const LiquidState& liquid, const EntrainmentTagTable& previous,
                                  const BubbleSettings& settings, double time) {
  validateLiquidState(liquid);
  // Where the liquid's velocity around a particle stays within entrainmentSpeed of the particle's
  // own, no probe can pass the speed test: it is skipped unread (the same decisions, faster).
  std::optional<VelocityRange> range;
  if (entrainmentUsesVelocityRange(settings)) range.emplace(liquid.velocity, liquid.grid);
  return detectEntrainment(liquid, previous, settings, time, range ? &*range : nullptr);
}

namespace {

/// What every particle's test of one step reads.
struct StepContext {
  const LiquidState& liquid;
  const BubbleSettings& settings;
  double time;                 ///< the end of the step [s]
  double band;                 ///< bandCells·h [m]
  double growth;               ///< entrainmentDepthCells·h [m]
  double probe;                ///< probeCells·h [m]
  bool speedTest;              ///< entrainmentSpeed is finite
  const VelocityRange* range;  ///< nullptr: no speed test is skipped
  double boundBelow;           ///< a speed bound below this cannot pass the test [m/s]
  /// Per stencil base cell, whether φ there is beyond ±band (empty: not built).
  const std::vector<std::uint8_t>& beyondBand;
};

/// Particle p, with its record from the previous step (or nullptr): its tag, test and seed, added
/// to `out` (detectEntrainment's rules, bubble_entrainment.h).
void testParticle(const StepContext& c, std::size_t p, const EntrainmentTag* old,
                  BlockResult& out) {
  const LiquidState& liquid = c.liquid;
  const BubbleSettings& settings = c.settings;
  const double time = c.time;
  const Vec3f& xf = liquid.particlePositions[p];
  const Vec3 x{xf[0], xf[1], xf[2]};
  // Deep or far, and no record: nothing to do (most particles), decided without the
  // interpolation.
  if (!old && !c.beyondBand.empty() && c.beyondBand[stencilBase(liquid.grid, x)]) return;
  // One set of loads for φ and, if the speed is tested, its gradient.
  const CellCentreStencil phiAround(liquid.liquidDistance, liquid.grid, x);
  const double phi = phiAround.value();
  const bool inBand = std::abs(phi) <= c.band;
  if (!old && !inBand) return;
  out.tagged += inBand;
  EntrainmentTag tag = old ? *old : EntrainmentTag{liquid.particleIds[p]};
  const double depth = -phi;
  if (!(time - tag.seedBirth < settings.seedLifetime)) {
    const bool windowOpen = time - tag.windowStart <= settings.entrainmentWindow;
    bool entrains = windowOpen && depth - tag.windowDepth >= c.growth;
    if (!entrains && inBand && c.speedTest) {
      const Vec3f& vf = liquid.particleVelocities[p];
      const Vec3 v{vf[0], vf[1], vf[2]};
      entrains =
          !(c.range && c.range->maxDifference(x, v) < c.boundBelow) &&
          relativeSpeedIntoLiquid(liquid, phiAround, x, v, c.probe) >= settings.entrainmentSpeed;
    }
    if (entrains) {
      tag.seedBirth = time;
      tag.windowStart = kNever;
      ++out.newSeeds;
    } else if (!windowOpen) {
      tag.windowStart = inBand ? time : kNever;
      tag.windowDepth = inBand ? depth : 0.0;
    }
  }
  const bool seedAlive = time - tag.seedBirth < settings.seedLifetime;
  if (seedAlive)
    out.seeds.push_back({tag.particleId, x, tag.seedBirth,
                         std::exp(-(time - tag.seedBirth) / settings.potentialDecayTime)});
  if (seedAlive || time - tag.windowStart <= settings.entrainmentWindow) out.tags.push_back(tag);
}

/// Particles [begin, end), each record looked up kPrefetchAhead particles early and fetched into
/// the cache then; the ring holds what was found until its particle comes.
void testBlock(const StepContext& c, const EntrainmentTagTable& previous, std::size_t begin,
               std::size_t end, BlockResult& out) {
  out.tags.reserve(end - begin);  // at most one record per particle: one allocation
  std::array<const EntrainmentTag*, kPrefetchAhead> found{};
  const auto lookAhead = [&](std::size_t q) {
    const EntrainmentTag* record = previous.find(c.liquid.particleIds[q]);
    if (record) __builtin_prefetch(record);
    found[q % kPrefetchAhead] = record;
  };
  for (std::size_t q = begin; q < std::min(end, begin + kPrefetchAhead); ++q) lookAhead(q);
  for (std::size_t p = begin; p < end; ++p) {
    const EntrainmentTag* old = found[p % kPrefetchAhead];
    if (p + kPrefetchAhead < end) lookAhead(p + kPrefetchAhead);  // takes old's slot
    testParticle(c, p, old, out);
  }
}

/// The blocks' records and seeds in block order; the sorts by id make the result independent of
/// the particles' order.
EntrainmentStep mergeBlocks(std::vector<BlockResult>& blocks) {
  EntrainmentStep result;
  std::vector<EntrainmentTag> tags;
  std::size_t records = 0, seeds = 0;
  for (const BlockResult& b : blocks) records += b.tags.size(), seeds += b.seeds.size();
  tags.reserve(records);
  result.seeds.reserve(seeds);
  for (BlockResult& b : blocks) {
    tags.insert(tags.end(), b.tags.begin(), b.tags.end());
    result.seeds.insert(result.seeds.end(), b.seeds.begin(), b.seeds.end());
    result.taggedParticles += b.tagged;
    result.newSeeds += b.newSeeds;
  }
  result.tags = EntrainmentTagTable(std::move(tags));
  std::sort(result.seeds.begin(), result.seeds.end(),
            [](const BubbleSeed& a, const BubbleSeed& b) { return a.particleId < b.particleId; });
  return result;
}

}  // namespace

EntrainmentStep detectEntrainment(const LiquidState& liquid, const EntrainmentTagTable& previous,
                                  const BubbleSettings& settings, double time,
                                  const VelocityRange* range) {
  validateLiquidState(liquid);
  const double h = liquid.grid.cellSize;
  const double band = settings.bandCells * h;
  if (!entrainmentUsesVelocityRange(settings)) range = nullptr;  // a probe beyond its reach
  const std::size_t n = liquid.particlePositions.size();
  const std::vector<std::uint8_t> beyondBand =
      n * kCellsPerParticleForTable >= liquid.liquidDistance.values().size()
          ? beyondBandStencils(liquid.liquidDistance, band)
          : std::vector<std::uint8_t>{};
  const StepContext context{liquid,
                            settings,
                            time,
                            band,
                            settings.entrainmentDepthCells * h,
                            settings.probeCells * h,
                            std::isfinite(settings.entrainmentSpeed),
                            range,
                            settings.entrainmentSpeed * (1.0 - kSpeedBoundMargin),
                            beyondBand};
  std::vector<BlockResult> blocks((n + kBlockParticles - 1) / kBlockParticles);
  forEachBlock(n, kBlockParticles, [&](std::size_t b, std::size_t begin, std::size_t end) {
    testBlock(context, previous, begin, end, blocks[b]);
  });
  return mergeBlocks(blocks);
}

}  // namespace fluidsound::sim
