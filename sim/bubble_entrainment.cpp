// sim/bubble_entrainment.cpp — see bubble_entrainment.h.
#include "sim/bubble_entrainment.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sim/block_parallel.h"
#include "sim/cell_interpolation.h"
#include "sim/particle_transfer.h"
#include "sim/random_stream.h"

namespace fluidsound::sim {

namespace {

/// Particles per parallel block: large enough to amortise a task, small enough to balance.
constexpr std::size_t kBlockParticles = 4096;
/// Filter bits per record: a deep particle passes the filter (and pays a binary search) with
/// probability ≈ 1/kFilterBitsPerTag.
constexpr std::size_t kFilterBitsPerTag = 16;
/// Below this |∇φ| [-] (φ is a distance, |∇φ| ≈ 1 near the surface) the normal is undefined: the
/// particle sits where φ is flat (e.g. the solver's constant far value), and the speed test is skipped.
constexpr double kMinimumDistanceGradient = 0.1;

/// The trilinear interpolant at x mixes the 8 centres around x, which include x's own cell centre
/// and lie within √3 cells of it; a distance field changes by at most its distance, so
/// |φ(x) − φ(own centre)| ≤ √3 h: a cheap test that leaves most particles out.
constexpr double kStencilReachCells = 1.7320508075688772;

std::uint64_t filterSlot(std::uint64_t id) { return cellStream(0, id); }

/// φ at the centre of the cell holding x (indices clamped to the grid).
float ownCellValue(const Array3f& phi, const GridGeometry& grid, const Vec3& x) {
  const Vec3 g = grid.gridFromWorld(x);
  int c[3];
  for (int a = 0; a < 3; ++a) c[a] = std::clamp(static_cast<int>(std::floor(g[a])), 0, grid.cells[a] - 1);
  return phi(c[0], c[1], c[2]);
}

/// The records and seeds one block of particles produced.
struct BlockResult {
  std::vector<EntrainmentTag> tags;
  std::vector<BubbleSeed> seeds;
  std::size_t tagged = 0, newSeeds = 0;
};

/// The speed at which particle velocity v moves into the liquid relative to the liquid
/// probe·h beneath x along the inward normal [m/s]; −∞ where the normal is undefined.
double relativeSpeedIntoLiquid(const LiquidState& liquid, const Vec3& x, const Vec3& v, double probeDistance) {
  const FieldSample phi = sampleCellCentres(liquid.liquidDistance, liquid.grid, x);
  const Vec3& g = phi.gradient;
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

EntrainmentTagTable::EntrainmentTagTable(std::vector<EntrainmentTag> tags) : tags_(std::move(tags)) {
  std::sort(tags_.begin(), tags_.end(),
            [](const EntrainmentTag& a, const EntrainmentTag& b) { return a.particleId < b.particleId; });
  for (std::size_t i = 1; i < tags_.size(); ++i)
    if (tags_[i].particleId == tags_[i - 1].particleId) {
      std::ostringstream message;
      message << "LiquidState.particleIds must be unique, but id " << tags_[i].particleId
              << " belongs to two particles";
      throw std::invalid_argument(message.str());
    }
  if (tags_.empty()) return;
  const std::uint64_t bits = std::bit_ceil(std::max<std::uint64_t>(64, kFilterBitsPerTag * tags_.size()));
  mask_ = bits - 1;
  filter_.assign(bits / 64, 0);
  for (const EntrainmentTag& t : tags_) {
    const std::uint64_t slot = filterSlot(t.particleId) & mask_;
    filter_[slot >> 6] |= std::uint64_t{1} << (slot & 63);
  }
}

const EntrainmentTag* EntrainmentTagTable::find(std::uint64_t id) const {
  if (tags_.empty()) return nullptr;
  const std::uint64_t slot = filterSlot(id) & mask_;
  if (!((filter_[slot >> 6] >> (slot & 63)) & 1)) return nullptr;
  const auto it = std::lower_bound(tags_.begin(), tags_.end(), id,
                                   [](const EntrainmentTag& t, std::uint64_t key) { return t.particleId < key; });
  return it != tags_.end() && it->particleId == id ? &*it : nullptr;
}

EntrainmentStep detectEntrainment(const LiquidState& liquid, const EntrainmentTagTable& previous,
                                  const BubbleSettings& settings, double time) {
  validateLiquidState(liquid);
  const double h = liquid.grid.cellSize;
  const double band = settings.bandCells * h;
  const double quickBand = band + kStencilReachCells * h;
  const double growth = settings.entrainmentDepthCells * h;
  const double probe = settings.probeCells * h;
  const bool speedTest = std::isfinite(settings.entrainmentSpeed);
  const std::size_t n = liquid.particlePositions.size();
  std::vector<BlockResult> blocks((n + kBlockParticles - 1) / kBlockParticles);
  forEachBlock(n, kBlockParticles, [&](std::size_t b, std::size_t begin, std::size_t end) {
    BlockResult& out = blocks[b];
    for (std::size_t p = begin; p < end; ++p) {
      const Vec3f& xf = liquid.particlePositions[p];
      const Vec3 x{xf[0], xf[1], xf[2]};
      const EntrainmentTag* old = previous.find(liquid.particleIds[p]);
      // Deep or far, and no record: nothing to do (almost every particle), decided without the
      // interpolation.
      if (!old && std::abs(ownCellValue(liquid.liquidDistance, liquid.grid, x)) > quickBand) continue;
      const double phi = interpolateCellCentres(liquid.liquidDistance, liquid.grid, x);
      const bool inBand = std::abs(phi) <= band;
      if (!old && !inBand) continue;
      out.tagged += inBand;
      EntrainmentTag tag = old ? *old : EntrainmentTag{liquid.particleIds[p]};
      const double depth = -phi;
      if (!(time - tag.seedBirth < settings.seedLifetime)) {
        const bool windowOpen = time - tag.windowStart <= settings.entrainmentWindow;
        bool entrains = windowOpen && depth - tag.windowDepth >= growth;
        if (!entrains && inBand && speedTest) {
          const Vec3f& vf = liquid.particleVelocities[p];
          entrains = relativeSpeedIntoLiquid(liquid, x, {vf[0], vf[1], vf[2]}, probe) >= settings.entrainmentSpeed;
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
  });
  // Merge in block order; the sorts by id make the result independent of the particles' order.
  EntrainmentStep result;
  std::vector<EntrainmentTag> tags;
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

}  // namespace fluidsound::sim
