// Tests of sim/fluid/fluid_solver.h: whole substeps of the liquid solver on coarse grids.
#include "sim/fluid/fluid_solver.h"
#include "sim/fluid/liquid_surface.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/solid_geometry.h"
#include "support/rest_measure.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/task_arena.h>

#include <cmath>
#include <iostream>

namespace fluidsound::sim {
namespace {

/// A closed box tank, liquid to `level` [m]; 16 × 16 × 16 cells of 1 cm.
FluidScene tank(double level) {
  FluidScene s;
  s.domain.max = {0.16, 0.16, 0.16};
  s.domain.cell = 0.01;
  s.time.duration = 1.0;
  s.liquid.push_back({Box{{0, 0, 0}, {0.16, level, 0.16}}, {}});
  return s;
}

/// A coarse dam break: a 0.1 × 0.2 m column at the −x wall of a 0.5 × 0.3 × 0.05 m box.
FluidScene damBreak() {
  FluidScene s;
  s.domain.max = {0.5, 0.3, 0.05};
  s.domain.cell = 0.01;
  s.time.duration = 1.0;
  s.liquid.push_back({Box{{0, 0, 0}, {0.1, 0.2, 0.05}}, {}});
  return s;
}

// Projection leaves the velocity divergence-free to the solver tolerance: the issue asks for
// max|∇·u|·Δx/|u|max < 1e-4 in liquid cells after each step; a 1e-6 relative residual gives
// ~1e-6 (the residual is a divergence, scaled by the same Δx/|u|).
TEST(FluidSolver, DamBreakStaysDivergenceFreeAndConverges) {
  FluidSolver solver(damBreak());
  const FrameStats stats = solver.advanceTo(0.2);
  EXPECT_GT(stats.substeps, 1);
  EXPECT_TRUE(stats.pressureConverged);
  EXPECT_LT(stats.maxDivergence, 1e-4);
  EXPECT_GT(stats.maxSpeed, 1.0) << "the column must be collapsing: ~√(2 g 0.2 m) ≈ 2 m/s";
}

// Claim (issue 4): the liquid volume changes by less than 2 % over 3 s of a dam break, by
// particle count at every frame (the column 0.1 × 0.2 m of scenes/dam_break.scene.json, 1 cm
// cells, advanced frame by frame at 30 fps as `simulate` does, so the once-per-frame density
// correction and reseeding run). Measured: −0.2 % (clumps thinned above 16 per cell).
// Reference: frame 0. Tolerance: the 2 %.
// The level set's volume (the default surface) is held to the start volume once per frame, at
// most half a cell per shift: measured +0.5 % at 3 s, at most +3 % in the splash; checked to 5 %
// (the particle surface alone read +1.2 % at 3 s and up to +17 % in the splash).
TEST(FluidSolver, DamBreakKeepsItsVolumeForThreeSeconds) {
  FluidScene scene = damBreak();
  scene.domain.max[2] = 0.1;
  scene.liquid[0].shape = Box{{0, 0, 0}, {0.1, 0.2, 0.1}};
  FluidSolver solver(scene);
  const double particles = static_cast<double>(solver.particles().size());
  const double volume = liquidVolume(solver.liquidDistance(), solver.grid());
  FrameStats stats;
  for (int frame = 1; frame <= 90; ++frame) {
    stats = solver.advanceTo(frame / 30.0);
    ASSERT_NEAR(static_cast<double>(stats.particles), particles, 0.02 * particles) << "frame " << frame;
    ASSERT_LT(stats.maxDivergence, 1e-4) << "frame " << frame;
    ASSERT_EQ(stats.particlesDeleted, 0u) << "a closed box loses nothing";
  }
  EXPECT_NEAR(stats.liquidVolume, volume, 0.05 * volume);
  for (const Vec3f& x : solver.particles().position) {
    ASSERT_GE(x[1], 0.0f);
    ASSERT_LE(x[0], 0.5f);
  }
}

// Determinism (brief): the same scene gives the same particles, bit for bit, on 1 and 2 threads.
TEST(FluidSolver, IdenticalParticlesForAnyThreadCount) {
  std::vector<Vec3f> one, two;
  oneapi::tbb::task_arena(1).execute([&] {
    FluidSolver s(damBreak());
    s.advanceTo(0.1);
    one = s.particles().position;
  });
  oneapi::tbb::task_arena(2).execute([&] {
    FluidSolver s(damBreak());
    s.advanceTo(0.1);
    two = s.particles().position;
  });
  EXPECT_EQ(one, two);
}

// The particle surface (solver.surface = "particles") in the same tanks: a regression bound,
// not the goal. Its bumps start gravity waves (the fastest particles move vertically at the
// surface): measured 2.3 mm/s at 2 s for the flat tank (median 0.3 mm/s), 2.9 mm/s over the 15°
// slope; the level set (below) reaches the issue's < 1 mm/s. Bounds 3 and 5 mm/s.
TEST(FluidSolver, ParticleSurfaceTanksStayNearlyAtRest) {
  FluidScene flatTank = tank(0.0735);
  flatTank.solver.surface = SurfaceMethod::Particles;
  FluidSolver flat(flatTank);
  FrameStats stats;
  for (int frame = 1; frame <= 60; ++frame) {
    stats = flat.advanceTo(frame / 30.0);
    ASSERT_LT(stats.maxDivergence, 1e-4) << "frame " << frame;
  }
  EXPECT_LT(stats.maxSpeed, 0.003);
  FluidScene scene = tank(0.0735);
  Solid slope;
  slope.shape = Box{{-0.05, -0.1, -0.05}, {0.21, 0.02, 0.21}};
  slope.rotateDegrees = {0.0, 0.0, 15.0};
  scene.solids.push_back(slope);
  scene.solver.surface = SurfaceMethod::Particles;
  FluidSolver sloped(scene);
  for (int frame = 1; frame <= 60; ++frame) stats = sloped.advanceTo(frame / 30.0);
  EXPECT_LT(stats.maxSpeed, 0.005);
}

// Claim (issue 4): a tank at rest stays at rest — after 2 s simulated the fastest particle moves
// at < 1 mm/s and the surface height varies by < 0.1 cell — with the liquid's top inside a row
// of cells (7.35 cells) and on a plane of cell faces (8 cells), where the particle surface alone
// left 2.3 and 10 mm/s (docs/solver.md). The level set starts flat and nothing disturbs it:
// measured 0 m/s and a spread of 0 (to float round-off). Reference: rest. Tolerance: the
// issue's 1 mm/s and 0.1 cell.
TEST(FluidSolver, RestingTankStaysAtRest) {
  for (const double level : {0.0735, 0.08}) {
    SCOPED_TRACE(level);
    const test::RestMeasure m = test::restAfter(tank(level), 2.0);
    EXPECT_LT(m.maxSpeed, 1e-3);
    EXPECT_LT(m.heightSpread, 0.1 * 0.01);
    EXPECT_EQ(m.columns, 16 * 16);
    std::cout << "[ measured ] level " << level << " m: max speed " << m.maxSpeed << " m/s, height spread "
              << m.heightSpread / 0.01 << " cell\n";
  }
}

// Claim (issue 4): the same over a sloped floor (a box rotated 15° about z, meeting the −x wall
// under 7 cm of water), where the contact line runs along a slanted wall: < 1 mm/s and a spread
// < 0.1 cell after 2 s (the particle surface alone: 2.9 mm/s). Measured: 0 m/s, spread 0.
// Reference: rest. Tolerance: the issue's.
TEST(FluidSolver, SlopedFloorTankStaysAtRest) {
  FluidScene scene = tank(0.0735);
  Solid slope;
  slope.shape = Box{{-0.05, -0.1, -0.05}, {0.21, 0.02, 0.21}};
  slope.rotateDegrees = {0.0, 0.0, 15.0};
  scene.solids.push_back(slope);
  const test::RestMeasure m = test::restAfter(scene, 2.0);
  EXPECT_LT(m.maxSpeed, 1e-3);
  EXPECT_LT(m.heightSpread, 0.1 * 0.01);
  EXPECT_GT(m.columns, 16 * 16 / 2);
  std::cout << "[ measured ] sloped floor: max speed " << m.maxSpeed << " m/s, height spread " << m.heightSpread / 0.01
            << " cell over " << m.columns << " columns\n";
}

// Claim (issue 4): the same against a curved solid wall — a sphere solid (r = 5 cm) rising
// through the surface, its contact line a circle on the curved wall (the particle surface alone:
// 7 mm/s and, before the cut-cell rules, 13–23 cm/s). Measured: 0 m/s, spread 0.
// Reference: rest. Tolerance: the issue's.
TEST(FluidSolver, TankAroundACurvedSolidStaysAtRest) {
  FluidScene scene = tank(0.0735);
  Solid sphere;
  sphere.shape = Sphere{{0.08, 0.05, 0.08}, 0.05};
  scene.solids.push_back(sphere);
  const test::RestMeasure m = test::restAfter(scene, 2.0);
  EXPECT_LT(m.maxSpeed, 1e-3);
  EXPECT_LT(m.heightSpread, 0.1 * 0.01);
  EXPECT_GT(m.columns, 16 * 16 / 2);
  std::cout << "[ measured ] sphere through the surface: max speed " << m.maxSpeed << " m/s, height spread "
            << m.heightSpread / 0.01 << " cell over " << m.columns << " columns\n";
}

}  // namespace
}  // namespace fluidsound::sim
