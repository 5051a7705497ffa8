// sim/bubbles/bubble_settings.h — bubble model: every parameter of entrainment detection, bubble seeds,
// bubble creation and bubble motion, with units and defaults (meaning and tuning: docs/bubbles.md).
#pragma once

#include <limits>

#include "sim/bubbles/bubble_rise.h"
#include "sim/bubbles/bubble_size_distribution.h"

namespace fluidsound::sim {

/// The bubble model's settings (the scene's optional "bubbles" block, parsed by io/). The model
/// after Zheng & James (2009, "Harmonic Fluids", §bubble generation [memory: the structure —
/// tags, seeds with a decaying potential, Poisson creation, density sampling with a sparse-seed
/// rejection — is theirs; their constants were not available, so every default here is our own
/// choice, stated with its reason]).
struct BubbleSettings {
  // --- 1. Tagging: which particles are at the free surface -------------------------------------
  /// Half-width of the tagging band [cells]: a particle with |φ| ≤ bandCells·h is at the surface.
  /// 1 cell: the top two particle layers at 8 particles per cell.
  double bandCells = 1.0;

  // --- 2. Entrainment: when a particle becomes a bubble seed -----------------------------------
  /// Depth growth [cells] that marks a seed: a particle tagged at depth d₀ that reaches
  /// d₀ + entrainmentDepthCells·h within `entrainmentWindow` was carried under the surface.
  /// Two cells: well above the φ noise of a particle surface (a fraction of a cell).
  double entrainmentDepthCells = 2.0;
  /// Window of the depth-growth test [s], opened when a particle is tagged. Growth over a window
  /// means a mean speed into the liquid ≥ entrainmentDepthCells·h / entrainmentWindow (0.5 m/s
  /// at h = 5 mm), far above a glass filling or a sloshing surface.
  double entrainmentWindow = 0.02;
  /// Speed into the liquid that marks a seed [m/s]: a tagged particle whose velocity, relative to
  /// the liquid probeCells·h beneath it along the surface normal, points into the liquid at this
  /// speed or more. 1 m/s: the critical (inception) speed of air entrainment by plunging water
  /// jets, ≈ 1 m/s (Ervine, McKeogh & Elsawy 1980; Bin 1993, Chem. Eng. Sci. 48:3585 [memory]).
  /// +∞ switches the test off.
  double entrainmentSpeed = 1.0;
  /// Depth of the reference point of the speed test [cells]: relative, not absolute, velocity,
  /// so a falling blob or a sloshing surface (all moving together) does not entrain.
  double probeCells = 2.0;

  // --- 3. Seeds --------------------------------------------------------------------------------
  /// Seed lifetime [s]: a seed makes bubbles for this long after its birth, then is dropped
  /// (and its particle may entrain again). 0.1 s: three frames at 30 fps.
  double seedLifetime = 0.1;
  /// Potential decay time τ [s]: a seed's potential is e^(−age/τ) (1 at birth). 0.03 s: an
  /// entrained air cavity breaks up into bubbles within tens of milliseconds [choice]. +∞: no decay.
  double potentialDecayTime = 0.03;

  // --- 4. Creation -----------------------------------------------------------------------------
  /// Creation rate constant k [1/s]: each step draws Poisson(k · Σ potential · dt) creation
  /// attempts. One seed makes k·τ(1 − e^(−L/τ)) attempts on average (L = seedLifetime): 0.58 with
  /// the defaults. ≥ 0; 0 makes no bubbles.
  double rate = 20.0;
  /// Radius distribution and its bounds, which are the minimum and maximum bubble radii [m]:
  /// Deane & Stokes (2002) power law on 0.1–5 mm with a_H = 1 mm by default (physics.md §7.2), or
  /// a truncated normal (GaussianBubbleSizes).
  BubbleSizeDistribution sizes = PowerLawBubbleSizes{};
  /// Radius of the sampling kernel around a chosen seed [cells]: a position is a seed's position
  /// plus a uniform offset in a ball of jitterCells·h, so positions are continuous. Half a cell:
  /// about the particle spacing at 8 particles per cell.
  double jitterCells = 0.5;
  /// Sparse-seed rejection: a position needs at least minSeeds live seeds within
  /// ρ(r) = max(neighbourhoodCells·h, neighbourhoodRadii·r) of it, so one stray particle pushed
  /// under the surface by numerical noise makes no bubble, and a large bubble needs seeds spread
  /// over a region comparable to its size. ≥ 1 (1: the chosen seed suffices, no rejection).
  int minSeeds = 3;
  double neighbourhoodCells = 1.0;  ///< [cells], ≥ 0
  double neighbourhoodRadii = 4.0;  ///< [bubble radii], ≥ 0; not both 0

  // --- 5. Motion -------------------------------------------------------------------------------
  /// Buoyant rise and drag (Tomiyama et al. 1998, contaminated water by default; bubble_rise.h).
  BubbleRiseSettings rise;

  bool operator==(const BubbleSettings&) const = default;

  /// The smallest and largest radius the distribution draws [m].
  double minRadius() const;
  double maxRadius() const;
};

/// @brief Checks every field of `settings`.
/// @throws std::invalid_argument "BubbleSettings.<field> must be <expectation>, got <value>"
///         (sizes and rise settings: "BubbleSettings.sizes: …", "BubbleSettings.rise: …" with the
///         sampler's or the rise model's own message naming the field).
void validateBubbleSettings(const BubbleSettings& settings);

}  // namespace fluidsound::sim
