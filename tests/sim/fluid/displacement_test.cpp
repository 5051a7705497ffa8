// tests/sim/displacement_test.cpp — issue 5's displacement acceptance: a sphere lowered slowly
// into a tank raises the level by V_sphere / A_tank (Archimedes: the liquid's volume is kept and
// the solid takes V of the space below the surface).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "sim/fluid/fluid_solver.h"

namespace fluidsound::sim {
namespace {

constexpr double kSide = 0.2, kCell = 0.01, kLevel = 0.10, kRadius = 0.04;  // [m]

/// A closed 20 × 25 × 20 cm tank of 1 cm cells, water to 10 cm, and (when `withSphere`) a 4 cm
/// sphere lowered on a path at 6 cm/s from clear above the water (bottom 2 cm above it) to fully
/// under it (top 1 cm below the still level), reached at 1.83 s, then held.
FluidScene tank(bool withSphere) {
  FluidScene s;
  s.domain.max = {kSide, 0.25, kSide};
  s.domain.cell = kCell;
  s.time.duration = 4.0;
  s.liquid.push_back({Box{{0, 0, 0}, {kSide, kLevel, kSide}}, {}});
  if (withSphere) {
    Solid sphere;
    sphere.shape = Sphere{{0.1, 0.16, 0.1}, kRadius};
    sphere.path = {{0.0, {0, 0, 0}}, {0.11 / 0.06, {0, -0.11, 0}}};
    s.solids.push_back(sphere);
  }
  return s;
}

/// Mean height [m] of the surface over the columns within 3 cm of the tank's walls (away from
/// the sphere's own disturbance): in each column, where φ at the cell centres crosses zero going
/// up, linearly interpolated.
double wallSideLevel(const FluidSolver& solver) {
  const Array3f& phi = solver.liquidDistance();
  const GridGeometry& grid = solver.grid();
  double sum = 0.0;
  int columns = 0;
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int i = 0; i < grid.cells[0]; ++i) {
      if (i >= 3 && i < grid.cells[0] - 3 && k >= 3 && k < grid.cells[2] - 3) continue;
      for (int j = 0; j + 1 < grid.cells[1]; ++j)
        if (phi(i, j, k) < 0.0f && phi(i, j + 1, k) >= 0.0f) {
          const double f = phi(i, j, k) / (phi(i, j, k) - phi(i, j + 1, k));
          sum += grid.cellCentre(i, j, k)[1] + f * grid.cellSize;
          ++columns;
          break;
        }
    }
  return sum / columns;
}

/// The wall-side level averaged over the frames of t = 2 … 4 s (the sphere at rest from 1.83 s),
/// which averages out the slosh the descent left.
double settledLevel(bool withSphere) {
  FluidSolver solver(tank(withSphere));
  double sum = 0.0;
  int frames = 0;
  for (int frame = 1; frame <= 120; ++frame) {
    solver.advanceTo(frame / 30.0);
    if (frame > 60) sum += wallSideLevel(solver), ++frames;
  }
  return sum / frames;
}

// Claim (issue 5): the level rises by V_sphere / A_tank = (4/3)π (4 cm)³ / (20 cm)² = 6.70 mm.
// Reference: Archimedes. Measured against the same tank without the sphere (run for the same time
// with the same seed), so the particle surface's own offset from the seeded top cancels.
// Tolerance: 5 % of the rise (the figure; 0.34 mm = 0.034 cell). Measured −2.6 % with
// the level-set surface (+4.4 % with the particle surface).
TEST(Displacement, LoweredSphereRaisesTheLevelByItsVolumeOverTheTankArea) {
  const double expected = 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3) / (kSide * kSide);
  const double without = settledLevel(false), with = settledLevel(true);
  std::printf("displacement: level %.5f m without, %.5f m with the sphere: rise %.3f mm, V/A %.3f mm (%+.1f %%)\n",
              without, with, 1e3 * (with - without), 1e3 * expected, 100.0 * ((with - without) / expected - 1.0));
  EXPECT_NEAR(with - without, expected, 0.05 * expected);
}

}  // namespace
}  // namespace fluidsound::sim
