// sim/bubbles/bubble_entrainment.h — bubble model, steps 1–2: tag the particles at the free surface and
// mark as bubble seeds those carried under it (depth growth within a window) or driven into the
// liquid beneath them (normal speed); keeps each particle's record by its id between steps.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "sim/bubbles/bubble_settings.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/liquid_state.h"
#include "sim/fluid/velocity_range.h"

namespace fluidsound::sim {

/// "Never": a time before every other, so `now − never` is +∞ and exceeds any window or lifetime.
inline constexpr double kNever = -std::numeric_limits<double>::infinity();

/// One particle's entrainment record, kept between steps by particle id (value type).
struct EntrainmentTag {
  std::uint64_t particleId = 0;
  double windowStart = kNever;  ///< [s] when the particle was tagged and its window opened
  double windowDepth = 0.0;     ///< [m] its depth −φ then (negative above the surface)
  double seedBirth = kNever;    ///< [s] when it last became a seed
  bool operator==(const EntrainmentTag&) const = default;
};

/// The records of one step, sorted by particle id. Ids as the solver numbers them (dense from 0)
/// are looked up in a table of one slot per id; other ids by binary search behind a
/// one-bit-per-slot hash filter: nearly every particle is deep and has no record, and both answer
/// "no" for it with one memory read.
class EntrainmentTagTable {
 public:
  EntrainmentTagTable() = default;
  /// @throws std::invalid_argument when two records share a particle id (ids must be unique)
  explicit EntrainmentTagTable(std::vector<EntrainmentTag> tags);

  /// The record of particle `id`, or nullptr.
  const EntrainmentTag* find(std::uint64_t id) const;
  std::span<const EntrainmentTag> tags() const { return tags_; }
  std::size_t size() const { return tags_.size(); }

 private:
  static constexpr std::uint32_t kNoSlot = 0xFFFFFFFFu;
  std::vector<EntrainmentTag> tags_;  ///< sorted by particleId
  std::vector<std::uint32_t> slotOfId_;  ///< dense ids: the index of id's record in tags_, or kNoSlot
  std::vector<std::uint64_t> filter_; ///< other ids: bit (mix(id) & mask) set for every record
  std::uint64_t mask_ = 0;
};

/// A live bubble seed: a liquid particle that entrained air, and its creation potential.
struct BubbleSeed {
  std::uint64_t particleId = 0;
  Vec3 position{0.0, 0.0, 0.0};  ///< the particle's position now [m]
  double birth = 0.0;            ///< [s]
  double potential = 0.0;        ///< e^(−age/τ) [-], 1 at birth
  bool operator==(const BubbleSeed&) const = default;
};

/// What detectEntrainment found at the end of one step.
struct EntrainmentStep {
  EntrainmentTagTable tags;       ///< the records to pass to the next step
  std::vector<BubbleSeed> seeds;  ///< every live seed, sorted by particle id
  std::size_t taggedParticles = 0;  ///< particles inside the tagging band now
  std::size_t newSeeds = 0;         ///< particles that became seeds in this step
};

/// @brief Tags, entrainment tests and seed bookkeeping for every particle, at time `time` (the end
///        of the step). Per particle, with band = bandCells·h and depth d = −φ(x):
///        - a live seed (time − birth < seedLifetime) stays a seed, with potential e^(−age/τ);
///        - otherwise it becomes a seed if its window is open (time − windowStart ≤
///          entrainmentWindow) and d − windowDepth ≥ entrainmentDepthCells·h, or if |φ| ≤ band and
///          (v_p − u(x − n·probeCells·h))·(−n) ≥ entrainmentSpeed, n = ∇φ/|∇φ|;
///        - otherwise a closed window reopens at (time, d) if |φ| ≤ band, or the record is dropped.
/// @param liquid    its liquidDistance is read as a true signed distance. Two shortcuts leave the
///                  decisions unchanged: with many particles per cell, a particle without a record
///                  whose interpolation stencil lies wholly beyond ±band is skipped unread (with
///                  few, the whole-grid table costs more than it saves), and a speed test that the
///                  range of the grid velocity around the particle cannot pass (velocity_range.h)
///                  is not run
/// @param previous  the tags returned by the previous step (empty at the start)
/// @note Bit-identical for any thread count and any order of the particle arrays: particles are
///       processed in fixed blocks and records and seeds are sorted by particle id.
/// @throws std::invalid_argument as validateLiquidState, or for duplicate particle ids among tags
EntrainmentStep detectEntrainment(const LiquidState& liquid, const EntrainmentTagTable& previous,
                                  const BubbleSettings& settings, double time);

/// @brief As above, with the velocity range of `liquid.velocity` built by the caller (the bubble
///        model builds it while the surface distance is rebuilt); nullptr: no speed test is skipped.
///        The decisions are the same with or without it.
EntrainmentStep detectEntrainment(const LiquidState& liquid, const EntrainmentTagTable& previous,
                                  const BubbleSettings& settings, double time, const VelocityRange* range);

/// Whether detectEntrainment can skip speed tests by a VelocityRange with these settings: the test
/// is on and its probe lies within the range's reach.
bool entrainmentUsesVelocityRange(const BubbleSettings& settings);

}  // namespace fluidsound::sim
