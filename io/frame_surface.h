// io/frame_surface.h — reading back a frame's liquid surface (frames/NNNN.vdb, grid `surface`)
// for the transfer stage: the level set sampled at world points (acoustics::LevelSetSampler), and
// the frames of an output folder as acoustics::LevelSetFrames (the local plane above a bubble is
// the transfer stage's, acoustics/transfer/level_set_surface.h).
#pragma once

#include <filesystem>
#include <memory>
#include <utility>

#include "acoustics/transfer/level_set_frames.h"

namespace fluidsound::io {

/// One frame's `surface` level set, loaded for sampling (OpenVDB kept out of this header).
class FrameLevelSet : public acoustics::LevelSetSampler {
 public:
  /// @throws InputError if the file is missing, unreadable or has no FloatGrid named `surface`
  explicit FrameLevelSet(const std::filesystem::path& path);
  ~FrameLevelSet() override;
  FrameLevelSet(FrameLevelSet&&) noexcept;
  FrameLevelSet& operator=(FrameLevelSet&&) noexcept;

  /// φ at `x` [m]: OpenVDB's trilinear BoxSampler in world space, the float value widened.
  double phi(const Vec3& x) const override;
  double bandHalfWidth() const override;  ///< |background| of the grid [m]
  double voxelSize() const override;      ///< the grid's voxel size along x [m]

 private:
  struct Grid;
  std::unique_ptr<Grid> grid_;
};

/// The frames `fluidsound simulate` wrote into OUTDIR: frame f is OUTDIR/frames/NNNN.vdb, opened
/// as its FrameLevelSet.
class FrameFolderLevelSets : public acoustics::LevelSetFrames {
 public:
  explicit FrameFolderLevelSets(std::filesystem::path outdir) : outdir_(std::move(outdir)) {}
  /// @throws InputError as FrameLevelSet's constructor
  std::unique_ptr<const acoustics::LevelSetSampler> open(int frame) const override;

 private:
  std::filesystem::path outdir_;
};

}  // namespace fluidsound::io
