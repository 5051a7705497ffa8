// Tests of sim/fluid/density_correction.h: moving particles so the liquid keeps its volume.
#include "sim/fluid/density_correction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <oneapi/tbb/task_arena.h>

#include <cmath>

#include "sim/fluid/liquid_surface.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/solid_geometry.h"

namespace fluidsound::sim {
namespace {

constexpr double kCell = 0.01;    // h [m]
constexpr int kSide = 16;         // cells per side of the closed tank
constexpr double kLevel = 0.0735; // liquid depth [m]
constexpr double kRadius = 0.4 * kCell;  // the solver's particle radius at 8 per cell

/// A closed 16³ tank of 1 cm cells, its solid boundary, and the particles.
struct Tank {
  FluidScene scene;
  GridGeometry grid;
  SolidMeshRays noMeshes;
  SolidBoundary solids;
  Particles particles;
  PressureSolver solver;

  Tank() {
    scene.domain.max = {kSide * kCell, kSide * kCell, kSide * kCell};
    scene.domain.cell = kCell;
    scene.time.duration = 1.0;
    scene.liquid.push_back({Box{{0, 0, 0}, {kSide * kCell, kLevel, kSide * kCell}}, {}});
    grid = scene.grid();
    solids = solidBoundaryAt(grid, scene.domain, scene.solids, noMeshes, 0.0);
  }

  /// One correction, as the solver makes it once per frame.
  DensityCorrectionReport correct() {
    const CellIndex index = sortParticlesByCell(particles, grid);
    const Array3f phi = liquidDistanceFromParticles(particles, index, grid, kRadius);
    PressureSettings settings;
    settings.tolerance = 1e-3;
    return correctParticleDensity(particles, index, DensityCorrectionInput{phi, phi, 8, 0.0},
                                  solids, solver, settings);
  }
  Array3f density() {
    const CellIndex index = sortParticlesByCell(particles, grid);
    return relativeParticleDensity(particles, index, grid, 8);
  }
  /// RMS of ρ/ρ₀ − 1 over the cells at least a cell below the surface [-].
  double rmsDensityError() {
    const Array3f rho = density();
    double sum = 0.0;
    int n = 0;
    for (int k = 0; k < kSide; ++k)
      for (int j = 0; j < 6; ++j)
        for (int i = 0; i < kSide; ++i, ++n) sum += (rho(i, j, k) - 1.0) * (rho(i, j, k) - 1.0);
    return std::sqrt(sum / n);
  }
  /// Mean height of the particle surface over the columns away from the walls [m].
  double meanSurface() {
    const CellIndex index = sortParticlesByCell(particles, grid);
    const Array3f phi = liquidDistanceFromParticles(particles, index, grid, kRadius);
    double sum = 0.0;
    int n = 0;
    for (int k = 1; k < kSide - 1; ++k)
      for (int i = 1; i < kSide - 1; ++i)
        for (int j = 0; j + 1 < kSide; ++j)
          if (phi(i, j, k) < 0.0f && phi(i, j + 1, k) >= 0.0f) {
            sum += (j + 0.5 + phi(i, j, k) / (phi(i, j, k) - phi(i, j + 1, k))) * kCell;
            ++n;
            break;
          }
    return sum / n;
  }
};

/// 2 × 2 × 2 particles per cell on the sub-cell centres, up to `layers` sub-cell layers.
Particles lattice(int layers) {
  Particles p;
  for (int k = 0; k < 2 * kSide; ++k)
    for (int j = 0; j < layers; ++j)
      for (int i = 0; i < 2 * kSide; ++i)
        p.push({float((i + 0.5) * kCell / 2), float((j + 0.5) * kCell / 2), float((k + 0.5) * kCell / 2)}, {});
  return p;
}

// Claim: the density measure reads exactly 1 for evenly spread particles, in the interior and in
// the cells against the walls and corners too (the weight of a missing centre beyond a wall is
// folded back), so a uniform liquid is not pushed towards or away from walls.
// Reference: 8 particles per cell on the sub-cell centres. Tolerance: float round-off.
TEST(DensityCorrection, UniformParticlesReadOneEverywhereBelowTheSurface) {
  Tank tank;
  tank.particles = lattice(12);  // 6 full cells
  const Array3f rho = tank.density();
  for (int k = 0; k < kSide; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < kSide; ++i) ASSERT_NEAR(rho(i, j, k), 1.0, 1e-5) << i << " " << j << " " << k;
  EXPECT_NEAR(rho(5, 5, 5), 0.875, 1e-5) << "half a cell below the top: 7/8 of the tent is liquid";
}

// Claim: a clump (8 extra particles in one interior cell: ρ = 1.86) spreads: its excess falls
// with every correction and the particles it pushes stay in the liquid.
// Reference: the cell's own excess before. Tolerance: the first correction removes at least a
// quarter of the excess (measured 36 %; the loose 1e-3 solve and the trilinear sampling of the
// displacement leave the rest for the next frames).
TEST(DensityCorrection, AClumpSpreads) {
  Tank tank;
  tank.particles = lattice(14);  // liquid to 7 cells
  for (int q = 0; q < 8; ++q)
    tank.particles.push({0.085f + 0.001f * (q % 2), 0.035f + 0.001f * ((q / 2) % 2), 0.085f + 0.001f * (q / 4)}, {});
  double excess = tank.density()(8, 3, 8) - 1.0;
  ASSERT_GT(excess, 0.8);
  for (int pass = 0; pass < 3; ++pass) {
    const double before = excess;
    tank.correct();
    excess = tank.density()(8, 3, 8) - 1.0;
    EXPECT_LT(excess, (pass == 0 ? 0.75 : 1.0) * before) << "pass " << pass;
  }
  for (const Vec3f& x : tank.particles.position) {
    for (int a = 0; a < 3; ++a) ASSERT_GE(x[a], 0.0f);
    ASSERT_LT(x[1], 0.08f) << "a particle thrown out of the liquid";
  }
}

// Claim: the solver's own seeding (jittered within the middle half of each sub-cell) reads within
// the correction's dead band (±0.25) everywhere, so five corrections leave the particles where
// they are: a liquid at rest is not stirred by the correction (that stirring kept a resting tank
// moving at 17 mm/s, docs/solver.md). The clump test above shows the correction still acts.
// Reference: the seeded positions. Tolerance: RMS density error of the seeding below 0.1
// (measured 0.041), no particle moved by more than 1e-4 cell (the solve's round-off).
TEST(DensityCorrection, LeavesTheSeededLiquidAtRest) {
  Tank tank;
  tank.particles = seedLiquid(tank.grid, tank.scene.liquid, tank.solids.nodeDistance, 8, 1);
  const std::vector<Vec3f> seeded = tank.particles.position;
  EXPECT_LT(tank.rmsDensityError(), 0.1);
  for (int pass = 0; pass < 5; ++pass) tank.correct();
  ASSERT_EQ(tank.particles.size(), seeded.size());
  std::vector<Vec3f> moved = tank.particles.position;
  std::sort(moved.begin(), moved.end());
  std::vector<Vec3f> before = seeded;
  std::sort(before.begin(), before.end());
  for (std::size_t p = 0; p < moved.size(); ++p)
    for (int a = 0; a < 3; ++a) ASSERT_NEAR(moved[p][a], before[p][a], 1e-4 * kCell) << "particle " << p;
}

// Determinism (brief): the same particles move the same on 1 and 2 threads.
TEST(DensityCorrection, SamePositionsForAnyThreadCount) {
  const auto run = [](int threads) {
    std::vector<Vec3f> out;
    oneapi::tbb::task_arena(threads).execute([&] {
      Tank tank;
      tank.particles = seedLiquid(tank.grid, tank.scene.liquid, tank.solids.nodeDistance, 8, 3);
      tank.correct();
      out = tank.particles.position;
    });
    return out;
  };
  EXPECT_EQ(run(1), run(2));
}

}  // namespace
}  // namespace fluidsound::sim
