// sim/bubbles/bubble_spawning.h — bubble model, steps 3–5: the number of creation attempts of a step
// (Poisson, mean = rate × Σ potential × dt), and for each attempt a radius from the size
// distribution, a position by density sampling among the seeds, the rejection tests, and a
// continuous birth time inside the step.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sim/bubbles/bubble_entrainment.h"
#include "sim/bubbles/bubble_settings.h"
#include "sim/bubbles/bubble_size_distribution.h"
#include "sim/fluid/liquid_state.h"

namespace fluidsound::sim {

/// A bubble made by one accepted attempt.
struct SpawnedBubble {
  double radius = 0.0;           ///< [m]
  double birth = 0.0;            ///< [s], in (t, t + dt]
  Vec3 position{0.0, 0.0, 0.0};  ///< centre [m]
  double depth = 0.0;            ///< −φ at the centre [m], > radius
  bool operator==(const SpawnedBubble&) const = default;
};

/// What the attempts of one step came to.
struct SpawnCounts {
  double totalPotential = 0.0;  ///< Σ potential over the seeds [-]
  double meanAttempts = 0.0;    ///< rate · Σ potential · dt, the Poisson mean
  std::size_t attempts = 0;
  std::size_t created = 0;
  std::size_t rejectedOutside = 0;  ///< position outside the grid
  std::size_t rejectedSolid = 0;    ///< solid distance at the centre < radius (in or touching a solid)
  std::size_t rejectedAir = 0;      ///< depth ≤ radius: in air (φ ≥ 0) or breaking the surface
  std::size_t rejectedSparse = 0;   ///< fewer than minSeeds seeds within ρ(radius)
  SpawnCounts& operator+=(const SpawnCounts& o);
  bool operator==(const SpawnCounts&) const = default;
};

struct SpawnResult {
  std::vector<SpawnedBubble> bubbles;  ///< in attempt order
  SpawnCounts counts;
};

/// The step (t, t + dt] whose attempts spawnBubbles draws.
struct SpawnStep {
  double t = 0.0;   ///< its start [s]
  double dt = 0.0;  ///< its length [s]
  /// Its stream key (the caller derives it from the scene seed and step).
  std::uint64_t stream = 0;
};

/// @brief Draws and tests the creation attempts of the step (t, t + dt].
///        Attempt count: Poisson(rate · Σ potential · dt), Σ taken in seed order. Attempt a draws,
///        from its own stream cellStream(stream, a + 1): the radius (inverse CDF of `sizes`), a
///        seed with probability ∝ its potential, an offset uniform in the ball of radius
///        jitterCells·h, and the birth t + dt·(1 − u), u uniform in [0, 1). The position is
///        rejected outside the grid, where the solid distance (trilinear from the nodes) is
///        < radius, where the depth −φ (trilinear from the centres) is ≤ radius, or where fewer
///        than minSeeds seeds lie within ρ(r) = max(neighbourhoodCells·h, neighbourhoodRadii·r).
/// @param seeds   live seeds, in a fixed order (detectEntrainment's: by particle id)
/// @note Rejected attempts are not retried: the created rate is rate × Σ potential × acceptance.
SpawnResult spawnBubbles(std::span<const BubbleSeed> seeds, const LiquidState& liquid,
                         const BubbleSizeSampler& sizes, const BubbleSettings& settings,
                         const SpawnStep& step);

}  // namespace fluidsound::sim
