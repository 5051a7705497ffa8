// io/frame_surface.h — reading back a frame's liquid surface (frames/NNNN.vdb, grid `surface`)
// for the transfer stage: the free surface above a bubble as a local plane (point, normal, depth),
// and the frames of an output folder as the stage's acoustics::FrameSurfaces.
#pragma once

#include <filesystem>
#include <memory>
#include <utility>

#include "acoustics/transfer/image_source_transfer.h"
#include "acoustics/transfer/transfer_stage.h"

namespace fluidsound::io {

/// One frame's `surface` level set, loaded for queries (OpenVDB kept out of this header).
class FrameSurface : public acoustics::FrameSurface {
 public:
  /// @throws InputError if the file is missing, unreadable or has no FloatGrid named `surface`
  explicit FrameSurface(const std::filesystem::path& path);
  ~FrameSurface() override;
  FrameSurface(FrameSurface&&) noexcept;
  FrameSurface& operator=(FrameSurface&&) noexcept;

  /// @brief The free surface above a bubble as a plane: from the point `depth` above the centre
  ///        along `up` (the direction against gravity), the level set's gradient there gives the
  ///        normal n and one Newton step onto φ = 0 the surface point q; the depth is (q − centre)·n.
  ///        Where that point is outside the narrow band, the gradient is too weak (|∇φ| < ½) or
  ///        the projected depth is not positive, the plane is the horizontal one at the track's
  ///        depth (normal `up`).
  /// @param centre  bubble centre [m]; `depth` [m] > 0 from the track; `up` a unit vector
  acoustics::LocalSurface surfaceAbove(const Vec3& centre, double depth,
                                       const Vec3& up) const override;

 private:
  struct Grid;
  std::unique_ptr<Grid> grid_;
};

/// The frames `fluidsound simulate` wrote into OUTDIR: frame f is OUTDIR/frames/NNNN.vdb.
class FrameFolderSurfaces : public acoustics::FrameSurfaces {
 public:
  explicit FrameFolderSurfaces(std::filesystem::path outdir) : outdir_(std::move(outdir)) {}
  /// @throws InputError as FrameSurface's constructor
  std::unique_ptr<acoustics::FrameSurface> open(int frame) const override;

 private:
  std::filesystem::path outdir_;
};

}  // namespace fluidsound::io
