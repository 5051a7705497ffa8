// acoustics/transfer/level_set_frames.h — how the transfer stage reads a sequence of frames' liquid
// surfaces without reading files: each frame's level set φ as a sampler. io implements it for
// the frames `fluidsound simulate` writes (io/frame_surface.h); level_set_surface.h turns it
// into the stage's FrameSurfaces. docs/transfer.md.
#pragma once

#include <memory>

#include "sim/core/vec3.h"

namespace fluidsound::acoustics {

/// A frame's liquid level set φ [m], negative in the liquid, sampled at world points.
class LevelSetSampler {
 public:
  virtual ~LevelSetSampler() = default;
  /// φ at `x` [m], interpolated trilinearly from the voxels.
  virtual double phi(const Vec3& x) const = 0;
  /// |φ| outside the narrow band (the level set's background value) [m].
  virtual double bandHalfWidth() const = 0;
  /// The voxel size h [m], the step of the central-difference gradient.
  virtual double voxelSize() const = 0;
};

/// A sequence of frames' level sets.
class LevelSetFrames {
 public:
  virtual ~LevelSetFrames() = default;
  /// @return frame `frame`'s level set; may throw (e.g. a missing or unreadable file)
  virtual std::unique_ptr<const LevelSetSampler> open(int frame) const = 0;
};

}  // namespace fluidsound::acoustics
