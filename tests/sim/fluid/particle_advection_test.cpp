// tests/sim/fluid/particle_advection_test.cpp — what a particle keeps when a mesh wall stops its move.
// The glass pour at 2.5 mm cells blew up (docs/solver.md, "A stopped particle's affine part"):
// a particle stuck at the glass's floor corner kept its APIC affine part through every stop,
// wrote v + C·d onto faces no other particle reached, read a larger C back, and its speed grew
// by 26 % a substep until it was infinite at frame 6. Running that scene takes minutes, so this
// test checks the rule that ended it: a stopped particle loses its affine part, a free one keeps
// it. (Fails on the previous rule, which kept it.)
#include "sim/fluid/particle_advection.h"

#include <gtest/gtest.h>

#include <memory>

#include "support/test_meshes.h"

namespace fluidsound::sim {
namespace {

constexpr double kCell = 0.005;  // [m]
constexpr int kCells = 20;       // a 0.1 m cube

GridGeometry cubeGrid() {
  GridGeometry g;
  g.cells = {kCells, kCells, kCells};
  g.cellSize = kCell;
  return g;
}

/// A 2 mm wall at x ∈ [0.050, 0.052], wide in y and z: between two node planes, which the grid
/// does not see; only the ray queries stop particles at it.
Solid thinWall() {
  Solid s;
  MeshFile file{"wall.obj"};
  file.surface = std::make_shared<const TriangleMesh>(
      test::boxMesh({0.050f, -1.0f, -1.0f}, {0.052f, 1.0f, 1.0f}));
  s.shape = file;
  return s;
}

// Claim: in a uniform flow of 1 m/s along +x for 10 ms (a 1 cm move), the particle that starts
// 5 mm before the wall is stopped on its side (x < 0.050 m) with no velocity into it and its
// affine part cleared; the one that starts at x = 0.010 m moves freely (to 0.020 m) and keeps
// its velocity and affine part as they were. Reference: plane geometry (the move crosses the
// wall or it does not); the affine values are exact (copied or zeroed, no arithmetic).
TEST(ParticleAdvection, AParticleStoppedAtAMeshWallLosesItsAffinePart) {
  const GridGeometry g = cubeGrid();
  MacVelocity u(g);
  for (float& x : u[0].values()) x = 1.0f;
  const std::array<Vec3f, 3> affine = {
      {{3.0f, -2.0f, 1.0f}, {0.5f, 4.0f, -1.5f}, {-2.5f, 0.25f, 6.0f}}};
  Particles p;
  p.push({0.045f, 0.05f, 0.05f}, {1.0f, 0.0f, 0.0f});
  p.push({0.010f, 0.05f, 0.05f}, {1.0f, 0.0f, 0.0f});
  p.affine = {affine, affine};
  Domain domain;
  domain.max = {0.1, 0.1, 0.1};
  domain.cell = kCell;
  const Array3f farFromSolids(g.nodeCount(), 1.0f);
  const Solid wall = thinWall();
  const SolidMeshRays rays(std::span(&wall, 1));
  SolidBoundary solids;
  solids.grid = g;
  solids.domain = domain;
  solids.nodeDistance = farFromSolids;
  solids.meshes = &rays;
  advectParticles(p, u, solids, SolidTimes{0.0, 0.01}, 0.01);

  EXPECT_LT(p.position[0][0], 0.050f);
  EXPECT_GT(p.position[0][0], 0.049f);
  EXPECT_EQ(p.velocity[0][0], 0.0f);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(p.affine[0][a], (Vec3f{0.0f, 0.0f, 0.0f})) << "row " << a;

  EXPECT_NEAR(p.position[1][0], 0.020f, 1e-6f);
  EXPECT_EQ(p.velocity[1][0], 1.0f);
  EXPECT_EQ(p.affine[1], affine);
}

}  // namespace
}  // namespace fluidsound::sim
