// io/cache_particles.h — a cache frame's particles (issue 21; docs/import.md): an OpenVDB
// PointDataGrid with `P`, and `v` and `id` where present (Houdini's and Blender's point caches,
// `fluidsound simulate`'s frames), read in fluidsound's frame (metres, y up).
#pragma once

#include <filesystem>
#include <optional>

#include "io/cache_file.h"
#include "sim/liquid_frame.h"

namespace fluidsound::io {

/// @brief The particles of the first PointDataGrid in the OpenVDB file `path` (an intact file,
///        vdb_file_check.h), converted by `metresPerUnit` and `up` (cache_frame_reader.h);
///        none when the file holds no point grid. `v` (Vec3 float or double) gives each particle's
///        velocity [m/s] (empty when absent: the caller reads the velocity grid there); `id`
///        (int32 or int64) its id (empty when absent).
/// @throws InputError naming the file and the grid: `v` or `id` of another type, a NaN or
///         infinite position or velocity, two particles with one id
std::optional<sim::FrameParticles> readPointParticles(const std::filesystem::path& path,
                                                      double metresPerUnit, UpAxis up);

}  // namespace fluidsound::io
