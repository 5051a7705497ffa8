// tests/support/solver_like_field.h — a liquid field φ at cell centres as the solver's is
// (liquid_surface.h): a signed distance only near the surface, clamped to [−0.4 h, 1.5 h].
#pragma once

#include <algorithm>
#include <functional>

#include "sim/core/vec3.h"
#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"

namespace fluidsound::test {

/// φ at every cell centre of `g`: distance(centre) clamped to [−0.4 h, 1.5 h], h = g.cellSize.
inline sim::Array3f solverLikeField(const sim::GridGeometry& g,
                                    const std::function<double(const Vec3&)>& distance) {
  sim::Array3f phi(g.cells);
  for (int k = 0; k < g.cells[2]; ++k)
    for (int j = 0; j < g.cells[1]; ++j)
      for (int i = 0; i < g.cells[0]; ++i)
        phi(i, j, k) = static_cast<float>(
            std::clamp(distance(g.cellCentre(i, j, k)), -0.4 * g.cellSize, 1.5 * g.cellSize));
  return phi;
}

}  // namespace fluidsound::test
