// tests/support/rest_measure.h — how still liquid is judged still (issues 4 and 5): a scene
// simulated for some seconds with the level-set surface, then its fastest particle and the
// spread of its free-surface height.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>

#include "sim/fluid/fluid_solver.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/scene_mesh_distances.h"
#include "sim/fluid/solid_geometry.h"

namespace fluidsound::test {

/// The resting tanks' measures after `seconds` of 30-fps frames with the level-set surface
/// (solver.surface = level_set, docs/solver.md step 4): the fastest particle [m/s] and
/// the spread (highest − lowest) of the surface height [m] over the columns whose surface lies
/// outside every solid, each column's height where φ crosses zero going up (linear between the
/// two centres). Every frame's projection is also checked divergence-free (< 1e-4).
struct RestMeasure {
  double maxSpeed = 0.0, heightSpread = 0.0;
  int columns = 0;
};
inline RestMeasure restAfter(sim::FluidScene scene, double seconds) {
  scene.solver.surface = sim::SurfaceMethod::LevelSet;
  sim::FluidSolver solver(scene);
  sim::FrameStats stats;
  for (int frame = 1; frame <= static_cast<int>(seconds * 30.0 + 0.5); ++frame) {
    stats = solver.advanceTo(frame / 30.0);
    EXPECT_LT(stats.maxDivergence, 1e-4) << "frame " << frame;
  }
  const sim::Array3f& phi = solver.liquidDistance();
  const sim::GridGeometry& g = solver.grid();
  sim::Domain noWalls = scene.domain;
  noWalls.open.fill(true);
  const sim::Array3f solids = sim::solidNodeDistance(g, noWalls, scene.solids, solver.time(),
                                                     sim::sceneMeshDistances(scene, g).solids);
  RestMeasure m;
  m.maxSpeed = stats.maxSpeed;
  double lowest = 1e9, highest = -1e9;
  for (int k = 0; k < g.cells[2]; ++k)
    for (int i = 0; i < g.cells[0]; ++i)
      for (int j = 0; j + 1 < g.cells[1]; ++j) {
        if (!(phi(i, j, k) < 0.0f && phi(i, j + 1, k) >= 0.0f)) continue;
        const double f = phi(i, j, k) / (phi(i, j, k) - phi(i, j + 1, k));
        const Vec3 at{g.cellCentre(i, j, k)[0], g.cellCentre(i, j, k)[1] + f * g.cellSize,
                           g.cellCentre(i, j, k)[2]};
        if (sim::interpolateNodes(solids, g, at) >
            0.5 * g.cellSize) {  // a free surface, not a contact line
          lowest = std::min(lowest, at[1]);
          highest = std::max(highest, at[1]);
          ++m.columns;
        }
        break;
      }
  m.heightSpread = highest - lowest;
  return m;
}

}  // namespace fluidsound::test
