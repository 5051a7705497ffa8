// tests/sim/fluid/solid_mesh_rays_test.cpp — ray queries against mesh solids (Embree): where a move
// meets a wall, on which side the mover is left, walls thinner than any grid cell, edges of the
// mesh, moving solids. References are plane geometry; tolerances are Embree's float arithmetic
// (≈ 1e-7 relative to the coordinates, ~0.1 m here ⇒ ~1e-8 m) with margin.
#include "sim/fluid/solid_mesh_rays.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "io/mesh_closedness.h"
#include "support/test_meshes.h"

namespace fluidsound::sim {
namespace {

constexpr double kFloatTolerance = 1e-6;  // [m]: float coordinates of ~0.1 m, with margin
constexpr double kOffset = 5e-6;          // [m]: 1e-3 of a 5 mm cell (kMeshWallOffsetCells)

Solid meshSolid(const TriangleMesh& mesh, std::vector<PathKey> path = {}) {
  Solid s;
  MeshFile file{"test.obj"};
  file.surface = std::make_shared<const TriangleMesh>(mesh);
  s.shape = file;
  s.path = std::move(path);
  return s;
}

/// A wall 2 mm thick, x ∈ [0.050, 0.052], wide in y and z: thinner than half a 5 mm cell.
TriangleMesh thinWall() { return test::boxMesh({0.050f, -1.0f, -1.0f}, {0.052f, 1.0f, 1.0f}); }

TEST(SolidMeshRays, NoMeshSolidsMeansEveryQueryMisses) {
  // Claim: boxes and spheres are the grid's business; without mesh solids nothing is hit.
  Solid box;
  box.shape = Box{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
  const SolidMeshRays rays(std::span(&box, 1));
  EXPECT_TRUE(rays.empty());
  EXPECT_FALSE(rays.firstCrossing({-1, 0.5, 0.5}, {2, 0.5, 0.5}, 0, 0, kOffset));
  EXPECT_FALSE(rays.crosses({-1, 0.5, 0.5}, {2, 0.5, 0.5}, 0));
}

TEST(SolidMeshRays, MoveThroughAThinWallStopsOnItsOwnSide) {
  // Claim: a move from x = 0.040 to 0.060 across the 2 mm wall at x = 0.050 stops at
  // 0.050 − (1 … 2)·offset, normal (−1, 0, 0) facing where it came from; the reverse move stops
  // on the far side at 0.052 + (1 … 2)·offset. Reference: plane x = 0.050 / 0.052.
  const Solid wall = meshSolid(thinWall());
  const SolidMeshRays rays(std::span(&wall, 1));
  ASSERT_FALSE(rays.empty());
  const auto stop = rays.firstCrossing({0.040, 0.01, 0.02}, {0.060, 0.03, 0.02}, 0.0, 0.0, kOffset);
  ASSERT_TRUE(stop);
  EXPECT_LE(stop->position[0], 0.050 - kOffset + 1e-8);
  EXPECT_GE(stop->position[0], 0.050 - 2 * kOffset - 1e-8);
  EXPECT_NEAR(stop->position[1], 0.01 + 0.02 * 0.5, 2 * kOffset);  // at half the move, along it
  EXPECT_NEAR(stop->normal[0], -1.0, 1e-6);
  EXPECT_NEAR(stop->normal[1], 0.0, 1e-6);
  EXPECT_EQ(stop->wallVelocity, (Vec3{0, 0, 0}));
  const auto back = rays.firstCrossing({0.060, 0.01, 0.02}, {0.040, 0.01, 0.02}, 0.0, 0.0, kOffset);
  ASSERT_TRUE(back);
  EXPECT_GE(back->position[0], 0.052 + kOffset - 1e-8);
  EXPECT_LE(back->position[0], 0.052 + 2 * kOffset + 1e-8);
  EXPECT_NEAR(back->normal[0], 1.0, 1e-6);
}

TEST(SolidMeshRays, MovesThatDoNotReachTheWallAreFree) {
  // Claim: a move ending 0.1 mm short of the wall, or running parallel to it, crosses nothing.
  const Solid wall = meshSolid(thinWall());
  const SolidMeshRays rays(std::span(&wall, 1));
  EXPECT_FALSE(rays.firstCrossing({0.040, 0.0, 0.0}, {0.0499, 0.0, 0.0}, 0, 0, kOffset));
  EXPECT_FALSE(rays.firstCrossing({0.049, -0.5, 0.0}, {0.049, 0.5, 0.3}, 0, 0, kOffset));
  EXPECT_FALSE(rays.crosses({0.040, 0.0, 0.0}, {0.0499, 0.0, 0.0}, 0));
  EXPECT_TRUE(rays.crosses({0.040, 0.0, 0.0}, {0.0501, 0.0, 0.0}, 0));
  EXPECT_TRUE(rays.crosses({0.040, 0.0, 0.0}, {0.060, 0.0, 0.0}, 0));
}

TEST(SolidMeshRays, RaysThroughEdgesAndVerticesOfTheMeshAreNotMissed) {
  // Claim: robust (watertight) mode: moves aimed exactly at the shared diagonal edge of a face's
  // two triangles and at a corner vertex still hit. Reference: the box [0.05, 0.052]×[−1, 1]².
  const Solid wall = meshSolid(thinWall());
  const SolidMeshRays rays(std::span(&wall, 1));
  // The −x face's diagonal runs from (0.05, −1, −1) to (0.05, 1, 1): y = z on it.
  for (double y : {-0.75, -0.3, 0.0, 0.2, 0.9})
    EXPECT_TRUE(rays.crosses({0.04, y, y}, {0.06, y, y}, 0)) << "y = z = " << y;
  EXPECT_TRUE(rays.crosses({0.04, 0.0, 0.0}, {0.06, 0.0, 0.0}, 0));
}

TEST(SolidMeshRays, AGlassWallStopsEveryRadialMove) {
  // Claim: every radial move from inside a 2 mm glass wall (inner radius 30 mm, 48 facets) to
  // outside it, at 1000 angles and heights, is stopped inside (radius < 30 mm); every move within
  // the cavity is free. Reference: the glass's geometry (facets lie within the circles).
  const TriangleMesh glass = test::glassMesh(0.030, 0.002, 0.100, 0.004, 48);
  ASSERT_TRUE(io::meshClosedness(glass).closed());
  const Solid solid = meshSolid(glass);
  const SolidMeshRays rays(std::span(&solid, 1));
  const double pi = std::acos(-1.0);
  for (int n = 0; n < 1000; ++n) {
    const double angle = 2 * pi * n / 1000.0, y = 0.01 + 0.08 * ((n * 37) % 1000) / 1000.0;
    const Vec3 from{0.020 * std::cos(angle), y, 0.020 * std::sin(angle)};
    const Vec3 to{0.040 * std::cos(angle), y, 0.040 * std::sin(angle)};
    const auto stop = rays.firstCrossing(from, to, 0, 0, kOffset);
    ASSERT_TRUE(stop) << "angle " << angle;
    EXPECT_LT(std::hypot(stop->position[0], stop->position[2]), 0.030) << "angle " << angle;
    EXPECT_FALSE(rays.crosses({0.0, y, 0.0}, from, 0));
  }
}

TEST(SolidMeshRays, AMovingWallCarriesAParticleAtRest) {
  // Claim: a wall moving +x at 1 m/s over a particle at rest reaches it: the particle is left on
  // the wall's front face at the end of the step, with the wall's velocity. Reference: the wall
  // (x ∈ [0.050, 0.052] at t = 0) is at [0.0505, 0.0525] at t = 0.5 ms.
  const Solid wall = meshSolid(thinWall(), {{0.0, {0, 0, 0}}, {1.0, {1.0, 0, 0}}});
  const SolidMeshRays rays(std::span(&wall, 1));
  const Vec3 particle{0.0523, 0.0, 0.0};  // just beyond the wall's +x face at t = 0
  const auto stop = rays.firstCrossing(particle, particle, 0.0, 0.0005, kOffset);
  ASSERT_TRUE(stop);
  EXPECT_GE(stop->position[0], 0.0525 + kOffset - 1e-8);
  EXPECT_LE(stop->position[0], 0.0525 + 2 * kOffset + 1e-8);
  EXPECT_NEAR(stop->wallVelocity[0], 1.0, 1e-9);
  EXPECT_NEAR(stop->normal[0], 1.0, 1e-6);
  // Beyond the wall's reach in that step, nothing happens.
  EXPECT_FALSE(rays.firstCrossing({0.0530, 0, 0}, {0.0530, 0, 0}, 0.0, 0.0005, kOffset));
  // crosses() places the wall at the given time.
  EXPECT_TRUE(rays.crosses({0.040, 0, 0}, {0.060, 0, 0}, 0.0));
  EXPECT_FALSE(rays.crosses({0.040, 0, 0}, {0.060, 0, 0}, 0.5));  // the wall is at x ≈ 0.55 then
}

}  // namespace
}  // namespace fluidsound::sim
