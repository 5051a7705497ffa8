// io/cache_frame_reader.h — one frame of a liquid cache as fluidsound reads it (issue 21;
// docs/import.md): the liquid's signed distance [m] and velocity [m/s] at points given in
// fluidsound's frame (metres, y up), whatever the cache's units and up axis, read from the grids
// checkCacheFrame found.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>

#include "io/cache_file.h"
#include "io/cache_frame.h"
#include "sim/liquid_frame.h"
#include "sim/core/vec3.h"
#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"

namespace fluidsound::io {

/// @brief A point or direction in fluidsound's frame (y up) from the cache's frame: y up as it is;
///        z up (Blender) turned by −90° about x, (x, y, z) → (x, z, −y). Lengths are not scaled.
Vec3 fromCacheAxes(const Vec3& v, UpAxis up);
/// The inverse of fromCacheAxes.
Vec3 toCacheAxes(const Vec3& v, UpAxis up);

/// Where a frame's liquid is and its voxel, in fluidsound's frame.
struct CacheFrameExtent {
  /// Min and max voxel centre [m, y up] of the level set's active voxels; none when it has none.
  std::optional<std::array<Vec3, 2>> bounds;
  double voxelSize = 0.0;      ///< [m]
  bool hasPoints = false;      ///< the file holds a point grid (OpenVDB points)
};

/// @brief The extent of the level set of the frame at `path` (named as checkCacheFrame finds it)
///        from the file's grid metadata (`file_bbox_min`/`max`, which OpenVDB writes with every
///        grid) without reading its voxels; from the voxels when the metadata is absent.
/// @throws InputError as checkCacheFrame's file and name checks
CacheFrameExtent cacheFrameExtent(const std::filesystem::path& path, const CacheGridNames& names,
                                  double metresPerUnit, UpAxis up);

/// One checked frame, read in full.
class CacheFrameReader {
 public:
  /// @brief Checks (checkCacheFrame) and reads the frame at `path`.
  /// @throws InputError as checkCacheFrame
  CacheFrameReader(const std::filesystem::path& path, const CacheGridNames& names, double metresPerUnit, UpAxis up);
  /// @brief Reads the frame at `path`, checked before (checkCacheFrame), through the grids `checked`
  ///        names, and with `withPoints` its first point grid too (particles()).
  /// @throws InputError for an unreadable file
  CacheFrameReader(const std::filesystem::path& path, const CacheFrameGrids& checked, double metresPerUnit,
                   UpAxis up, bool withPoints);
  ~CacheFrameReader();
  CacheFrameReader(CacheFrameReader&&) noexcept;
  CacheFrameReader& operator=(CacheFrameReader&&) noexcept;

  /// φ [m] at x [m, y up], trilinear; negative in the liquid; ± the band's width outside it.
  double phi(const Vec3& x) const;
  /// The liquid's velocity [m/s, y up] at x [m, y up], trilinear.
  Vec3 velocity(const Vec3& x) const;
  /// φ [m] at every cell centre of `grid` (trilinear; exact voxel values where the centres are
  /// the voxels'), in parallel; the same values for any thread count.
  sim::Array3f cellCentrePhi(const sim::GridGeometry& grid) const;
  /// The velocity [m/s] on every face of `grid` (a MAC grid), trilinear from the velocity grid
  /// (OpenVDB's staggered sampling for a staggered grid, as Houdini's FLIP `vel` and fluidsound's
  /// `velocity` are); `known`, if given, marks the faces whose every stencil voxel holds a value
  /// (a cache's velocity covers the liquid and a band, and is 0 beyond).
  sim::MacVelocity faceVelocity(const sim::GridGeometry& grid,
                                std::array<sim::Array3<std::uint8_t>, 3>* known = nullptr) const;
  /// @brief The particles of the frame's first point grid (read with `withPoints`), in metres, y up;
  ///        none when the file has no point grid.
  /// @throws InputError as pointGridParticles (point_grid_particles.h)
  std::optional<sim::FrameParticles> particles() const;
  /// The voxel's edge [m].
  double voxelSize() const;
  /// Bounds [m, y up] of the level set's active voxels (the liquid's narrow band): min, max corner.
  std::array<Vec3, 2> bounds() const;

 private:
  struct Grids;
  std::unique_ptr<Grids> grids_;
  std::filesystem::path path_;
  double scale_ = 1.0;  ///< metres per unit
  UpAxis up_ = UpAxis::Y;
};

}  // namespace fluidsound::io
