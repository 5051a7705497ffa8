// sim/fluid/fluid_scene.cpp — see fluid_scene.h.
#include "sim/fluid/fluid_scene.h"

#include <cmath>

namespace fluidsound::sim {

GridGeometry FluidScene::grid() const {
  GridGeometry g;
  g.cellSize = domain.cell;
  g.origin = domain.min;
  for (int a = 0; a < 3; ++a)
    g.cells[a] = static_cast<int>(std::lround((domain.max[a] - domain.min[a]) / domain.cell));
  return g;
}

}  // namespace fluidsound::sim
