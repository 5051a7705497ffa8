// io/cache_frame.h — one frame of a liquid cache (issue 21; docs/import.md) checked before the
// bubble model reads it: the level set and the velocity grid it is read through, found by name,
// of the right types, on one uniform grid, with finite values. Houdini names them `surface` and
// `vel`, `fluidsound simulate` `surface` and `velocity`.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fluidsound::io {

/// The names a frame's grids are looked for under, in order: the first present is used.
struct CacheGridNames {
  std::vector<std::string> surface{"surface"};
  std::vector<std::string> velocity{"vel", "velocity"};
};

/// What checkCacheFrame found.
struct CacheFrameGrids {
  std::string surface, velocity;  ///< the grids' names
  double voxelSize = 0.0;         ///< their voxel's edge [the file's units]
};

/// @brief Checks `path`: an intact OpenVDB file (vdb_file_check.h) with a FloatGrid level set
///        under one of names.surface and a Vec3 float or double grid under one of
///        names.velocity, each with uniform voxels on a linear transform, the same transform for
///        both, and every value finite.
/// @throws InputError naming the file and the grid: missing (listing the file's grids), of
///         another type, non-uniform voxels, a transform unlike the level set's, a NaN or an
///         infinite value (with its voxel)
CacheFrameGrids checkCacheFrame(const std::filesystem::path& path, const CacheGridNames& names);

/// @brief The names of the grids checkCacheFrame would use, from the file's grid list alone (for a
///        frame already checked); voxelSize is left 0.
/// @throws InputError as checkCacheFrame for a missing grid or an unreadable file
CacheFrameGrids findCacheFrameGrids(const std::filesystem::path& path, const CacheGridNames& names);

}  // namespace fluidsound::io
