// sim/fluid/grid.h — the solver grid: a box of cubic cells in world space (metres, y up), and the
// conversions between world positions and grid coordinates (cell units, pbrt-style names).
#pragma once

#include <array>
#include <cmath>

#include "sim/core/vec3.h"
#include "sim/fluid/array3.h"

namespace fluidsound::sim {

/// The placement of the solver grid. Cell (i, j, k) spans world
/// [origin + (i, j, k)·cellSize, origin + (i+1, j+1, k+1)·cellSize]; its centre is at +0.5.
/// MAC faces: u at (i, j+½, k+½)·h (i = 0 … ni), v at (i+½, j, k+½)·h, w at (i+½, j+½, k)·h.
struct GridGeometry {
  Index3 cells{0, 0, 0};     ///< cell counts (ni, nj, nk)
  double cellSize = 0.0;     ///< h [m]
  Vec3 origin{0.0, 0.0, 0.0};  ///< world position of the grid's minimum corner [m]

  /// Grid coordinates (cell units, corner-based) of a world position [m].
  Vec3 gridFromWorld(const Vec3& p) const {
    return {(p[0] - origin[0]) / cellSize, (p[1] - origin[1]) / cellSize, (p[2] - origin[2]) / cellSize};
  }
  /// World position [m] of grid coordinates (cell units, corner-based).
  Vec3 worldFromGrid(const Vec3& g) const {
    return {origin[0] + g[0] * cellSize, origin[1] + g[1] * cellSize, origin[2] + g[2] * cellSize};
  }
  /// World position [m] of the centre of cell (i, j, k).
  Vec3 cellCentre(int i, int j, int k) const { return worldFromGrid({i + 0.5, j + 0.5, k + 0.5}); }

  /// Size of the face array of component `axis` (0 = u, 1 = v, 2 = w): one more along `axis`.
  Index3 faceCount(int axis) const {
    Index3 n = cells;
    ++n[axis];
    return n;
  }
  /// Size of the node (cell corner) array.
  Index3 nodeCount() const { return {cells[0] + 1, cells[1] + 1, cells[2] + 1}; }
};

}  // namespace fluidsound::sim
