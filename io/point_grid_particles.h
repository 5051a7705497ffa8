// io/point_grid_particles.h — an OpenVDB PointDataGrid's particles in fluidsound's frame (issue 21):
// `P`, and `v` and `id` where present. io-internal: the frame reader (cache_frame_reader.h) and
// the particle-file reader (cache_particles.h) share it.
#pragma once

#include <openvdb/points/PointDataGrid.h>

#include <string>

#include "io/cache_file.h"
#include "sim/liquid_frame.h"

namespace fluidsound::io {

/// @brief The grid's particles converted by `metresPerUnit` and `up` (cache_frame_reader.h).
/// @throws InputError naming `file` and the grid: `v` or `id` of another type, a NaN or infinite
///         position or velocity, two particles with one id
sim::FrameParticles pointGridParticles(const openvdb::points::PointDataGrid& grid, double metresPerUnit, UpAxis up,
                                       const std::string& file);

}  // namespace fluidsound::io
