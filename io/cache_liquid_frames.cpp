// io/cache_liquid_frames.cpp — see cache_liquid_frames.h.
#include "io/cache_liquid_frames.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "io/cache_frame_reader.h"
#include "io/cache_particles.h"
#include "io/input_error.h"

namespace fluidsound::io {

sim::GridGeometry cacheGrid(const CacheDescription& cache, const std::vector<SequenceFrame>& frames) {
  const bool framesHoldParticles = !cache.particles;
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3 hi{-lo[0], -lo[1], -lo[2]};
  double voxel = 0.0;
  for (const SequenceFrame& f : frames) {
    const CacheFrameExtent extent = cacheFrameExtent(f.path, cache.grids, cache.metresPerUnit, cache.up);
    if (framesHoldParticles && !extent.hasPoints)
      throw InputError(f.path.string(), "", "the liquid's particles as a point grid (OpenVDB points with P, v, id)",
                       "no point grid (a particle file pattern goes in the cache file's `particles`)");
    if (voxel == 0.0) voxel = extent.voxelSize;
    if (std::abs(extent.voxelSize - voxel) > 1e-6 * voxel) {
      std::ostringstream found;
      found << extent.voxelSize << " m (frame " << frames.front().frame << ": " << voxel << " m)";
      throw InputError(f.path.string(), cache.grids.surface.front(), "the voxel size of the sequence's first frame",
                       found.str());
    }
    if (!extent.bounds) continue;  // no liquid yet
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], (*extent.bounds)[0][a]), hi[a] = std::max(hi[a], (*extent.bounds)[1][a]);
  }
  sim::GridGeometry grid;
  grid.cellSize = voxel;
  if (cache.container) {  // the container's box, its cells the frames' voxels
    const Container& box = *cache.container;
    grid.origin = box.min;
    for (int a = 0; a < 3; ++a)
      grid.cells[a] = std::max(1, static_cast<int>(std::lround((box.max[a] - box.min[a]) / voxel)));
    return grid;
  }
  if (lo[0] > hi[0])
    throw InputError(cache.file.string(), "frames", "a liquid in at least one frame", "empty level sets in every frame");
  for (int a = 0; a < 3; ++a) {
    grid.cells[a] = static_cast<int>(std::lround((hi[a] - lo[a]) / voxel)) + 1 + 2 * kCacheGridMarginCells;
    grid.origin[a] = lo[a] - (0.5 + kCacheGridMarginCells) * voxel;  // cell centres on voxel centres
  }
  return grid;
}

CacheLiquidFrames::CacheLiquidFrames(const CacheDescription& cache, std::vector<SequenceFrame> frames,
                                     std::vector<SequenceFrame> particles, const sim::GridGeometry& grid)
    : cache_(cache), frames_(std::move(frames)), particles_(std::move(particles)), grid_(grid) {}

sim::LiquidFrame CacheLiquidFrames::frame(int i) {
  const SequenceFrame& f = frames_.at(static_cast<std::size_t>(i));
  // Every frame was checked by cacheGrid, before any output: read it once, its points with it.
  const CacheFrameReader reader(f.path, findCacheFrameGrids(f.path, cache_.grids), cache_.metresPerUnit, cache_.up,
                                particles_.empty());
  sim::LiquidFrame frame;
  frame.time = (f.frame - frames_.front().frame) / cache_.fps;
  frame.liquidDistance = reader.cellCentrePhi(grid_);
  frame.velocity = reader.faceVelocity(grid_, &frame.velocityKnown);
  const std::filesystem::path points = particles_.empty() ? f.path : particles_.at(static_cast<std::size_t>(i)).path;
  std::optional<sim::FrameParticles> particles =
      particles_.empty() ? reader.particles() : readPointParticles(points, cache_.metresPerUnit, cache_.up);
  if (!particles)
    throw InputError(points.string(), particles_.empty() ? "frames" : "particles",
                     "a point grid (OpenVDB points with P, v, id) holding the liquid's particles", "no point grid");
  frame.particles = std::move(*particles);
  return frame;
}

}  // namespace fluidsound::io
