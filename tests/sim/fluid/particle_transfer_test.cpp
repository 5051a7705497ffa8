// Tests of sim/fluid/particle_transfer.h, sim/fluid/particle_seeding.h, sim/fluid/liquid_surface.h,
// sim/fluid/particle_advection.h and sim/fluid/velocity_extrapolation.h: the particle half of the solver.
#include "sim/fluid/particle_transfer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/fluid/liquid_surface.h"
#include "sim/fluid/particle_advection.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/velocity_extrapolation.h"

namespace fluidsound::sim {
namespace {

GridGeometry testGrid(int n = 16, double h = 0.01) {
  GridGeometry g;
  g.cells = {n, n, n};
  g.cellSize = h;
  return g;
}

/// Node distances of an open space (no solids): +1 m everywhere.
Array3f noSolids(const GridGeometry& g) { return Array3f(g.nodeCount(), 1.0f); }

LiquidRegion boxRegion(Vec3 min, Vec3 max, Vec3 velocity = {}) { return {Box{min, max}, velocity}; }

// Stratified seeding puts exactly 8 particles in every cell inside a box aligned with cells.
TEST(ParticleSeeding, EightPerCellInsideAlignedBox) {
  const GridGeometry g = testGrid();
  const LiquidRegion r = boxRegion({0.0, 0.0, 0.0}, {0.05, 0.08, 0.16});
  const Particles p = seedLiquid(g, std::span(&r, 1), noSolids(g), 8, 1);
  EXPECT_EQ(p.size(), 5u * 8 * 16 * 8);
  for (const Vec3f& x : p.position) {
    EXPECT_LT(x[0], 0.05f);
    EXPECT_LT(x[1], 0.08f);
  }
}

// The seed and the cell decide the jitter: same input, same particles (any thread count).
TEST(ParticleSeeding, SameSeedSameParticles) {
  const GridGeometry g = testGrid();
  const LiquidRegion r = {Sphere{{0.08, 0.08, 0.08}, 0.05}, {}};
  const Particles a = seedLiquid(g, std::span(&r, 1), noSolids(g), 8, 7);
  const Particles b = seedLiquid(g, std::span(&r, 1), noSolids(g), 8, 7);
  const Particles c = seedLiquid(g, std::span(&r, 1), noSolids(g), 8, 8);
  EXPECT_EQ(a.position, b.position);
  EXPECT_NE(a.position, c.position);
}

// APIC transfers reproduce an affine velocity field exactly (Jiang et al. 2015: APIC conserves
// affine motion): u = (0.1 + 2y, −0.3 + 0.5z, 0.2 − x) survives P2G → G2P to float precision.
TEST(ParticleTransfer, ApicKeepsAffineVelocityField) {
  const GridGeometry g = testGrid();
  const LiquidRegion r = boxRegion({0.0, 0.0, 0.0}, {0.16, 0.16, 0.16});
  Particles p = seedLiquid(g, std::span(&r, 1), noSolids(g), 8, 3);
  const auto field = [](const Vec3f& x) {
    return Vec3f{0.1f + 2.0f * x[1], -0.3f + 0.5f * x[2], 0.2f - x[0]};
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.velocity[i] = field(p.position[i]);
    p.affine[i] = {Vec3f{0, 2, 0}, Vec3f{0, 0, 0.5f}, Vec3f{-1, 0, 0}};
  }
  sortParticlesByCell(p, g);
  MacVelocity u(g);
  std::array<Array3f, 3> w;
  particlesToGrid(p, g, TransferScheme::Apic, u, w);
  // P2G is exact on every face a particle reaches; G2P is exact where the whole stencil lies in
  // the grid, so particles within a cell of the grid's edge (clamped stencils) are not checked.
  const Particles before = p;
  gridToParticles(p, u, u, g, SolverSettings{});
  double worst = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    bool interior = true;
    for (int a = 0; a < 3; ++a) interior = interior && p.position[i][a] > 0.01f && p.position[i][a] < 0.15f;
    if (!interior) continue;
    for (int a = 0; a < 3; ++a) worst = std::max(worst, std::fabs(double(p.velocity[i][a]) - before.velocity[i][a]));
  }
  EXPECT_LT(worst, 1e-5) << "m/s; float rounding of values O(0.5 m/s)";
}

// Sorting by cell keeps each cell's particles together and the index finds them.
TEST(ParticleTransfer, SortIndexFindsEveryParticleInItsCell) {
  const GridGeometry g = testGrid(8);
  const LiquidRegion r = boxRegion({0.0, 0.0, 0.0}, {0.08, 0.04, 0.08});
  Particles p = seedLiquid(g, std::span(&r, 1), noSolids(g), 8, 5);
  std::reverse(p.position.begin(), p.position.end());
  const CellIndex index = sortParticlesByCell(p, g);
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) {
        const std::size_t c = (static_cast<std::size_t>(k) * 8 + j) * 8 + i;
        for (std::size_t q = index.start[c]; q < index.start[c + 1]; ++q) {
          EXPECT_EQ(static_cast<int>(std::floor(p.position[q][0] / 0.01f)), i);
          EXPECT_EQ(static_cast<int>(std::floor(p.position[q][2] / 0.01f)), k);
        }
      }
  EXPECT_EQ(index.start[8 * 8 * 8], p.size());
}

// The particle level set of a freshly seeded flat layer crosses zero within half a cell of the
// layer's top. (Measured: −0.35 … +0.15 cell with r = 0.4 h. The jittered particles make the
// Zhu–Bridson surface bumpy at that scale; issue 4 asks for < 0.1 cell after 2 s of a resting
// tank, which needs a smoother surface than this one: not reached yet.)
TEST(LiquidSurface, FlatLayerSurfaceWithinHalfACell) {
  const GridGeometry g = testGrid();
  const double top = 0.0735;  // between cell centres
  const LiquidRegion r = boxRegion({0.0, 0.0, 0.0}, {0.16, top, 0.16});
  Particles p = seedLiquid(g, std::span(&r, 1), noSolids(g), 8, 11);
  const CellIndex index = sortParticlesByCell(p, g);
  const Array3f phi = liquidDistanceFromParticles(p, index, g, 0.4 * g.cellSize);
  double lowest = 1e9, highest = -1e9;
  for (int k = 2; k < 14; ++k)
    for (int i = 2; i < 14; ++i)
      for (int j = 0; j + 1 < 16; ++j)
        if (phi(i, j, k) < 0 && phi(i, j + 1, k) >= 0) {
          const double y0 = (j + 0.5) * g.cellSize, y1 = y0 + g.cellSize;
          const double y = y0 + (y1 - y0) * phi(i, j, k) / (phi(i, j, k) - phi(i, j + 1, k));
          lowest = std::min(lowest, y);
          highest = std::max(highest, y);
        }
  EXPECT_NEAR(lowest, top, 0.5 * g.cellSize);
  EXPECT_NEAR(highest, top, 0.5 * g.cellSize);
}

// Midpoint-rule advection in a rigid rotation keeps particles on their circle to O(Δt³):

// Deep inside the liquid (all cells within 2 of a centre hold ≥ half the seeding count) the
// kernel sum is replaced by φ = −r (r = 0.4 h). Claims: the sum it skips reads within 0.1 h of −r
// there (measured 0.055 h: the kernel mean of a jittered uniform liquid lies that close to the
// centre), so both values are below −0.3 h, past the −h/8 and −h/4 below which the volume and
// density samples saturate; every other cell (the surface layer, cells near walls) keeps exactly
// the summed value; and the liquid volume read from either field is the same to the bit.
// Liquid: a tank filled to 8.35 cells, 8 particles per cell, as seeded.
TEST(LiquidSurface, InteriorShortcutMatchesTheKernelSum) {
  const GridGeometry g = testGrid();
  const LiquidRegion r = boxRegion({0.0, 0.0, 0.0}, {0.16, 0.0835, 0.16});
  const Particles p = seedLiquid(g, std::span(&r, 1), noSolids(g), 8, 11);
  Particles sorted = p;
  const CellIndex index = sortParticlesByCell(sorted, g);
  const double radius = 0.4 * g.cellSize;
  const Array3f summed = liquidDistanceFromParticles(sorted, index, g, radius);
  const Array3f shortcut = liquidDistanceFromParticles(sorted, index, g, radius, 4);
  int interior = 0, kept = 0;
  double worst = 0.0;
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        if (shortcut(i, j, k) == summed(i, j, k)) {
          ++kept;
          continue;
        }
        ASSERT_EQ(shortcut(i, j, k), static_cast<float>(-radius)) << i << " " << j << " " << k;
        ++interior;
        worst = std::max(worst, std::abs(summed(i, j, k) + radius) / g.cellSize);
      }
  // Cells 2 … 13 in x and z, 2 … 5 or 6 in y (the top row, 0.35 full, holds 4 or fewer).
  EXPECT_GE(interior, 12 * 4 * 12);
  EXPECT_LE(interior, 12 * 5 * 12);
  EXPECT_GT(kept, 16 * 16 * 16 / 2);
  EXPECT_LT(worst, 0.1);
  EXPECT_EQ(liquidVolume(shortcut, g), liquidVolume(summed, g));
  std::cout << "[ measured ] interior cells " << interior << ", largest |sum + r| " << worst << " h\n";
}
// one step of ω·Δt = 0.1 rad changes the radius by ≈ (ωΔt)³/… ≪ 1e-3 of it.
TEST(ParticleAdvection, RigidRotationKeepsRadius) {
  const GridGeometry g = testGrid(32, 0.01);
  MacVelocity u(g);
  const double omega = 2.0, c = 0.16;  // rad/s about (c, c) in the xy plane
  for (int k = 0; k < 32; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i <= 32; ++i) u[0](i, j, k) = static_cast<float>(-omega * ((j + 0.5) * 0.01 - c));
  for (int k = 0; k < 32; ++k)
    for (int j = 0; j <= 32; ++j)
      for (int i = 0; i < 32; ++i) u[1](i, j, k) = static_cast<float>(omega * ((i + 0.5) * 0.01 - c));
  Particles p;
  p.push({0.24f, 0.16f, 0.16f}, {});
  Domain d;
  d.max = {0.32, 0.32, 0.32};
  d.cell = 0.01;
  const SolidMeshRays noMeshes;
  SolidBoundary solids;
  solids.grid = g;
  solids.domain = d;
  solids.nodeDistance = noSolids(g);
  solids.meshes = &noMeshes;
  advectParticles(p, u, solids, SolidTimes{0.0, 0.05}, 0.05);
  const double radius = std::hypot(p.position[0][0] - c, p.position[0][1] - c);
  EXPECT_NEAR(radius, 0.08, 1e-3 * 0.08);
  EXPECT_NEAR(std::atan2(p.position[0][1] - c, p.position[0][0] - c), omega * 0.05, 1e-3);
}

// A solver reuses one TransferWorkspace every substep: the sort and P2G through a workspace that
// already served a different particle set give bit for bit what fresh buffers give (reference:
// the overloads without a workspace; tolerance: none, the arithmetic and its order are the same).
TEST(ParticleTransfer, ReusedWorkspaceGivesSameResultAsFreshBuffers) {
  const GridGeometry g = testGrid();
  const LiquidRegion sphere = {Sphere{{0.08, 0.08, 0.08}, 0.05}, {0.3, -0.2, 0.1}};
  const LiquidRegion box = boxRegion({0.0, 0.0, 0.0}, {0.07, 0.11, 0.16}, {-0.1, 0.4, 0.0});
  TransferWorkspace workspace;
  MacVelocity u(g), uFresh(g);
  std::array<Array3f, 3> w, wFresh;
  Particles first = seedLiquid(g, std::span(&sphere, 1), noSolids(g), 8, 11);
  sortParticlesByCell(first, g, workspace);
  particlesToGrid(first, g, TransferScheme::Apic, u, w, workspace);
  Particles reused = seedLiquid(g, std::span(&box, 1), noSolids(g), 8, 12);
  std::reverse(reused.position.begin(), reused.position.end());
  for (std::size_t i = 0; i < reused.size(); ++i) reused.affine[i] = {Vec3f{0.5f, 0, 0}, Vec3f{0, -1, 0}, Vec3f{0, 0, 2}};
  Particles fresh = reused;
  const CellIndex index = sortParticlesByCell(reused, g, workspace);
  const CellIndex indexFresh = sortParticlesByCell(fresh, g);
  EXPECT_EQ(index.start, indexFresh.start);
  EXPECT_EQ(reused.position, fresh.position);
  particlesToGrid(reused, g, TransferScheme::Apic, u, w, workspace);
  particlesToGrid(fresh, g, TransferScheme::Apic, uFresh, wFresh);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(u[a].values(), uFresh[a].values()) << "component " << a;
    EXPECT_EQ(w[a].values(), wFresh[a].values()) << "component " << a;
  }
}

// Extrapolation fills one more ring of faces per layer with the mean of its valid neighbours.
TEST(VelocityExtrapolation, FillsLayerByLayer) {
  GridGeometry g = testGrid(6);
  MacVelocity u(g);
  FaceMask valid;
  for (int a = 0; a < 3; ++a) valid[a] = Array3<std::uint8_t>(g.faceCount(a), 0);
  u[0](3, 3, 3) = 2.0f;
  valid[0](3, 3, 3) = 1;
  extrapolateVelocity(u, valid, 1);
  EXPECT_EQ(u[0](4, 3, 3), 2.0f);
  EXPECT_EQ(u[0](3, 2, 3), 2.0f);
  EXPECT_EQ(u[0](5, 3, 3), 0.0f);  // two faces away: not yet
  extrapolateVelocity(u, valid, 2);
  EXPECT_EQ(u[0](5, 3, 3), 2.0f);
}

}  // namespace
}  // namespace fluidsound::sim
