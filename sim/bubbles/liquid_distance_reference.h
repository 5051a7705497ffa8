// sim/bubbles/liquid_distance_reference.h — SurfaceDistance's field computed plainly, cell by cell
// and point by point, with none of rebuild's row skipping, task planes or buckets: the
// specification the fast version is tested against
// (tests/sim/bubbles/liquid_distance_reference_test.cpp). Not used by the bubble model: it costs
// cells × surface points.
#pragma once

#include <vector>

#include "sim/core/vec3.h"
#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"

namespace fluidsound::sim {

/// What surfaceDistanceReference found.
struct SurfaceDistanceReference {
  Array3f field;             ///< as SurfaceDistance::field() [m]
  std::vector<Vec3> points;  ///< the surface points [m], in cell order (x fastest)
};

/// @brief SurfaceDistance(phi, solidNodeDistance, grid, band, airBand).field() and its surface
///        points, the obvious way: classify each cell (solid when its 8 nodal solid distances sum
///        below 0, else liquid where φ < 0); give each cell with a non-solid 6-neighbour of the
///        other phase the foot of its perpendicular on the plane through its nearest axis
///        crossings; give every other cell the smallest squared distance to the points that reach
///        it, ±its side's band beyond. It keeps the fast version's rounding of each squared
///        distance (x² and y² + z² each rounded to float, summed in float) and its reach rule (a
///        point reaches the cells of its box of centres within band per axis whose row (j, k)
///        lies within band of it): those are its operations per value, which a double d² would
///        not give bit for bit.
/// @param airBand  0 for `band`; as SurfaceDistance otherwise (not checked here)
SurfaceDistanceReference surfaceDistanceReference(const Array3f& phi,
                                                  const Array3f& solidNodeDistance,
                                                  const GridGeometry& grid, double band,
                                                  double airBand = 0.0);

}  // namespace fluidsound::sim
