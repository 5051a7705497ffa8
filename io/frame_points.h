// io/frame_points.h — a frame's particles as an OpenVDB PointDataGrid (issue 21; docs/import.md):
// `P`, `v` and `id`, the attributes Houdini's and Blender's point caches use, so that a frame of
// `fluidsound simulate` carries its particles the way a cache from elsewhere does. io-internal: it
// hands OpenVDB grids to the frame writer.
#pragma once

#include <openvdb/openvdb.h>
#include <openvdb/points/PointDataGrid.h>

#include "sim/fluid/particles.h"

namespace fluidsound::io {

/// The grid's name in our frames (Houdini's VDB-from-particles names its point grid so too).
inline constexpr const char* kParticlePointsName = "points";

/// @brief The particles as a PointDataGrid on `transform` named kParticlePointsName: `P` (exact
///        floats), `v` [m/s] (Vec3f) and `id` (int64, the particle's stable id).
openvdb::points::PointDataGrid::Ptr particlePointGrid(const sim::Particles& particles,
                                                      const openvdb::math::Transform::Ptr& transform);

}  // namespace fluidsound::io
