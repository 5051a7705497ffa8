// tests/support/cube_grid.h — a cubic MAC grid at the origin, as the particle tests build it.
#pragma once

#include "sim/fluid/grid.h"

namespace fluidsound::test {

/// `cells` cells of size `cellSize` [m] along each axis, minimum corner at the origin.
inline sim::GridGeometry cubeGrid(int cells, double cellSize) {
  sim::GridGeometry g;
  g.cells = {cells, cells, cells};
  g.cellSize = cellSize;
  return g;
}

}  // namespace fluidsound::test
