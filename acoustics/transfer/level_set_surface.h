// acoustics/transfer/level_set_surface.h — the free surface above a bubble as a local plane, from a
// frame's liquid level set: the plane the image-source model (image_source_transfer.h) reflects in.
// The level sets come through a small sampling interface (level_set_frames.h), so this library
// reads no files (io/frame_surface.h samples frames/NNNN.vdb). docs/transfer.md.
#pragma once

#include <memory>
#include <utility>

#include "acoustics/transfer/image_source_transfer.h"
#include "acoustics/transfer/level_set_frames.h"
#include "acoustics/transfer/transfer_stage.h"

namespace fluidsound::acoustics {

/// @brief The free surface above a bubble as a plane: from the point `depth` above the centre
///        along `up` (the direction against gravity), the level set's gradient there (central
///        differences one voxel either side) gives the normal n and one Newton step onto φ = 0 the
///        surface point q; the depth is (q − centre)·n. Where that point is outside the narrow
///        band (|φ| ≥ 0.99 of its half width), the gradient is too weak (|∇φ| < ½) or the
///        projected depth is not positive, the plane is the horizontal one at the track's depth
///        (normal `up`).
/// @param centre  bubble centre [m]; `depth` [m] > 0 from the track; `up` a unit vector
LocalSurface localSurfacePlane(const LevelSetSampler& level, const Vec3& centre, double depth,
                               const Vec3& up);

/// One frame's surface for the transfer stage: localSurfacePlane over its level set.
class LevelSetFrameSurface : public FrameSurface {
 public:
  explicit LevelSetFrameSurface(std::unique_ptr<const LevelSetSampler> level)
      : level_(std::move(level)) {}
  LocalSurface surfaceAbove(const Vec3& centre, double depth, const Vec3& up) const override {
    return localSurfacePlane(*level_, centre, depth, up);
  }

 private:
  std::unique_ptr<const LevelSetSampler> level_;
};

/// The frames of a sequence for the transfer stage: each frame's level set, opened by `frames`,
/// as a LevelSetFrameSurface. `frames` must outlive it.
class LevelSetFrameSurfaces : public FrameSurfaces {
 public:
  explicit LevelSetFrameSurfaces(const LevelSetFrames& frames) : frames_(frames) {}
  std::unique_ptr<FrameSurface> open(int frame) const override {
    return std::make_unique<LevelSetFrameSurface>(frames_.open(frame));
  }

 private:
  const LevelSetFrames& frames_;
};

}  // namespace fluidsound::acoustics
