// io/cache_liquid_frames.h — a cache's OpenVDB frames as the bubble model reads them at the cache's
// rate (issue 21; docs/import.md): the grid they are sampled on, and each frame's level set,
// velocity and particles on it, in metres with y up.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "io/cache_file.h"
#include "io/frame_sequence.h"
#include "sim/cache_bubbles.h"
#include "sim/fluid/grid.h"

namespace fluidsound::io {

/// Cells the import's grid holds beyond the frames' liquid on every side.
inline constexpr int kCacheGridMarginCells = 2;

/// @brief The grid the import samples `frames` on, the frames' voxel as its cell: the cache's
///        container box from its min corner; without one, cell centres on the voxel centres,
///        covering the union of every frame's level-set extent (cacheFrameExtent) plus
///        kCacheGridMarginCells.
///        Every frame is checked here (checkCacheFrame), before any output is written.
/// @throws InputError naming the frame: a voxel size unlike the first frame's, no point grid when
///         the cache names no particle files, or as cacheFrameExtent
sim::GridGeometry cacheGrid(const CacheDescription& cache, const std::vector<SequenceFrame>& frames);

/// The frames of a cache, read one at a time (sim::LiquidFrameSource).
class CacheLiquidFrames : public sim::LiquidFrameSource {
 public:
  /// @param particles  one file per frame (the cache's `particles` pattern), or empty: the
  ///                   particles are the frame file's own point grid, if it has one
  CacheLiquidFrames(const CacheDescription& cache, std::vector<SequenceFrame> frames,
                    std::vector<SequenceFrame> particles, const sim::GridGeometry& grid);
  int frameCount() const override { return static_cast<int>(frames_.size()); }
  /// @throws InputError as checkCacheFrame, readPointParticles, or for a frame without particles
  sim::LiquidFrame frame(int i) override;

 private:
  const CacheDescription& cache_;
  std::vector<SequenceFrame> frames_, particles_;
  sim::GridGeometry grid_;
};

}  // namespace fluidsound::io
