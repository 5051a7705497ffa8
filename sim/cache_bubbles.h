// sim/cache_bubbles.h — the bubble model at a cache's frame rate (issue 21; docs/import.md): the
// simulate stage's other entry, for a liquid simulated elsewhere. Between two frames it steps the
// bubble model (bubble_model.h) on substeps whose liquid is interpolated in time: each particle
// on the Hermite curve between its places and velocities in the two frames (particle_paths.h;
// followed by id, or by nearest advected position where the cache has no ids), the surface made
// from those particles by the solver's own rule (liquid_surface.h), the grid velocity blended
// linearly. Bubbles are born at sub-frame times and carried by a velocity that changes within
// the frame. What changes against the in-solver model, with measurements: docs/import.md.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "sim/bubbles/bubble_history.h"
#include "sim/core/stage_observer.h"
#include "sim/fluid/grid.h"
#include "sim/liquid_frame.h"
#include "sim/scene.h"

namespace fluidsound::sim {

/// The frames of a cache, read one at a time in order (io implements it for OpenVDB files).
class LiquidFrameSource {
 public:
  virtual ~LiquidFrameSource() = default;
  virtual int frameCount() const = 0;
  /// @brief Frame i (0 … frameCount − 1, asked once each, in order) on the import's grid.
  virtual LiquidFrame frame(int i) = 0;
};

/// How the import steps the bubble model between frames and what surface it reads.
struct CacheImportSettings {
  /// Cells the liquid may move in one substep (the solver's CFL rule): the larger of the particles'
  /// largest displacement between the frames and the grid velocity's largest speed times the frame
  /// interval, over cfl·h, sets the count.
  double cfl = 1.0;
  /// At least this many substeps per entrainment window (bubble settings), so that a particle's
  /// depth growth is seen within it whatever the frame rate.
  int perEntrainmentWindow = 2;
  int maxPerFrame = 256;
  /// The particles' radius [cells] in the surface the bubble model reads, made from the particles
  /// at every substep (liquid_surface.h): the solver's rule, 0.8 × the spacing of 8 particles per
  /// cell. Not the cache's level set: that is smoothed (Houdini's and Blender's particle surfaces,
  /// fluidsound's own frames) and loses liquid thinner than a cell or two — a pouring jet — and
  /// blending two level sets in time moves no surge (measured: docs/import.md).
  double particleRadiusCells = 0.4;
};

/// One frame's record (report.json's `results.frames[]` of from-cache).
struct CacheFrameRecord {
  int frame = 0;              ///< index in the cache, from 0
  double time = 0.0;          ///< [s]
  std::size_t particles = 0;  ///< in the frame
  std::size_t followed = 0;   ///< of them, found in the frame before (by id or by position)
  int substeps = 0;           ///< from the frame before to this one (0 for the first)
  std::size_t bubblesAlive = 0, bubblesTotal = 0;
  double readSeconds = 0.0;    ///< wall time the import waited for the frame and checked it [s]: it is read
                               ///< while the bubble model steps towards the frame before (with 2+ threads)
  double bubbleSeconds = 0.0;  ///< wall time of the bubble model's substeps [s]
};

class CacheBubbleObserver : public StageObserver {
 public:
  /// Called after each frame, in order, with the frame the source gave.
  virtual void onFrame(const LiquidFrame& /*frame*/, const CacheFrameRecord& /*record*/) {}
};

struct CacheBubbleResult {
  std::vector<BubbleHistory> bubbles;      ///< every bubble made, in creation order
  std::vector<CacheFrameRecord> frames;    ///< the frames read
  std::optional<int> interruptedAt;        ///< the frame before which the observer stopped it
  double readSeconds = 0.0, bubbleSeconds = 0.0;  ///< totals [s]
};

/// @brief The bubble model of `scene.bubbles` (seed, gravity) over the source's frames on `grid`,
///        with the scene's solids (placed at each substep's time when they move) and the closed
///        faces of scene.domain as walls (bubbles that leave the grid end).
///        Deterministic: the same frames give the same bits for any thread count.
/// @throws std::invalid_argument for fewer than 2 frames, frames whose arrays do not fit `grid`,
///         particle velocities or ids whose count differs from the positions'
CacheBubbleResult cacheBubbles(LiquidFrameSource& source, const GridGeometry& grid, const Scene& scene,
                               const CacheImportSettings& settings, CacheBubbleObserver& observer);

}  // namespace fluidsound::sim
