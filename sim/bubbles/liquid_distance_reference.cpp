// sim/bubbles/liquid_distance_reference.cpp — see liquid_distance_reference.h.
#include "sim/bubbles/liquid_distance_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fluidsound::sim {

namespace {

enum class Phase { air, liquid, solid };

/// A cell next to the surface: its point, the distance to it [m], and the cells the point reaches
/// (lo ≤ index ≤ hi per axis).
struct SurfacePoint {
  Index3 cell;
  double distance;
  Vec3 point;
  Index3 lo, hi;
};

Phase phaseOf(const Array3f& phi, const Array3f& nodes, int i, int j, int k) {
  // The 8 nodes in the order (x, then y, then z) of the solver's extendIntoSolids rule.
  const float sum = nodes(i, j, k) + nodes(i + 1, j, k) + nodes(i, j + 1, k) +
                    nodes(i + 1, j + 1, k) + nodes(i, j, k + 1) + nodes(i + 1, j, k + 1) +
                    nodes(i, j + 1, k + 1) + nodes(i + 1, j + 1, k + 1);
  if (sum < 0.0f) return Phase::solid;
  return phi(i, j, k) < 0.0f ? Phase::liquid : Phase::air;
}

/// The surface point of cell c, if a non-solid 6-neighbour is of the other phase: along each axis
/// the nearer crossing h·φ_c/(φ_c − φ_n) (the first of −1, +1 on a tie); the centre itself when a
/// crossing is at 0, else the foot of the perpendicular on the plane through the crossings.
bool surfacePointOf(const Array3f& phi, const Array3<Phase>& phase, const GridGeometry& grid,
                    const Index3& c, SurfacePoint& out) {
  const Phase here = phase(c[0], c[1], c[2]);
  if (here == Phase::solid) return false;
  const double h = grid.cellSize, value = phi(c[0], c[1], c[2]);
  Vec3 inverse{0.0, 0.0, 0.0};  // s_a/(θ_a h) [1/m]
  bool crossing = false, onSurface = false;
  for (int a = 0; a < 3; ++a) {
    double nearest = std::numeric_limits<double>::infinity();
    int side = 0;
    for (const int step : {-1, 1}) {
      Index3 n = c;
      n[a] += step;
      if (n[a] < 0 || n[a] >= grid.cells[a]) continue;
      const Phase there = phase(n[0], n[1], n[2]);
      if (there == Phase::solid || there == here) continue;
      const double along = h * value / (value - phi(n[0], n[1], n[2]));
      if (along < nearest) nearest = along, side = step;
    }
    if (side == 0) continue;
    crossing = true;
    if (nearest <= 0.0)
      onSurface = true;
    else
      inverse[a] = side / nearest;
  }
  if (!crossing) return false;
  out.cell = c;
  const Vec3 centre = grid.cellCentre(c[0], c[1], c[2]);
  if (onSurface) {
    out.distance = 0.0, out.point = centre;
    return true;
  }
  const double d2 =
      1.0 / (inverse[0] * inverse[0] + inverse[1] * inverse[1] + inverse[2] * inverse[2]);
  out.distance = std::sqrt(d2);
  for (int a = 0; a < 3; ++a) out.point[a] = centre[a] + d2 * inverse[a];
  return true;
}

/// The box of cells whose centre lies within `band` of the point, per axis.
void setReach(SurfacePoint& s, const GridGeometry& grid, double band) {
  for (int a = 0; a < 3; ++a) {
    const double first = grid.cellCentre(0, 0, 0)[a];
    s.lo[a] =
        std::max(0, static_cast<int>(std::floor((s.point[a] - band - first) / grid.cellSize)) + 1);
    s.hi[a] = std::min(grid.cells[a] - 1,
                       static_cast<int>(std::floor((s.point[a] + band - first) / grid.cellSize)));
  }
}

/// The smallest squared distance [m²] from the centre x of cell c to the points that reach it
/// (+∞ for none), rounded as the fast version rounds it.
float nearestSquare(const std::vector<SurfacePoint>& points, const Index3& c, const Vec3& x,
                    double band) {
  float best = std::numeric_limits<float>::infinity();
  for (const SurfacePoint& s : points) {
    bool inBox = true;
    for (int a = 0; a < 3; ++a) inBox = inBox && s.lo[a] <= c[a] && c[a] <= s.hi[a];
    const double ex = x[0] - s.point[0], ey = x[1] - s.point[1], ez = x[2] - s.point[2];
    if (!inBox || !(ey * ey + ez * ez < band * band)) continue;
    best = std::min(best, static_cast<float>(ex * ex) + static_cast<float>(ey * ey + ez * ez));
  }
  return best;
}

}  // namespace

SurfaceDistanceReference surfaceDistanceReference(const Array3f& phi,
                                                  const Array3f& solidNodeDistance,
                                                  const GridGeometry& grid, double band,
                                                  double airBand) {
  if (airBand == 0.0) airBand = band;
  const Index3 n = grid.cells;
  Array3<Phase> phase(n);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) phase(i, j, k) = phaseOf(phi, solidNodeDistance, i, j, k);
  std::vector<SurfacePoint> points;
  Array3<int> pointOf(n, -1);  // a surface cell's index in points
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        SurfacePoint s;
        if (!surfacePointOf(phi, phase, grid, {i, j, k}, s)) continue;
        setReach(s, grid, band);
        pointOf(i, j, k) = static_cast<int>(points.size());
        points.push_back(s);
      }
  SurfaceDistanceReference result{Array3f(n), {}};
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const bool liquid = phase(i, j, k) != Phase::air;  // solid counts as liquid in the sign
        const double side = liquid ? band : airBand;
        double magnitude = 0.0;
        if (pointOf(i, j, k) >= 0) {  // next to the surface: the distance to its own point
          magnitude = std::min(points[pointOf(i, j, k)].distance, side);
        } else {
          const double d2 = nearestSquare(points, {i, j, k}, grid.cellCentre(i, j, k), band);
          magnitude = d2 <= side * side ? std::sqrt(d2) : side;
        }
        result.field(i, j, k) = static_cast<float>(liquid ? -magnitude : magnitude);
      }
  for (const SurfacePoint& s : points) result.points.push_back(s.point);
  return result;
}

}  // namespace fluidsound::sim
