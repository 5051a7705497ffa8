// Tests of sim/fluid/particle_reseeding.h: keeping 4–16 particles in every liquid cell.
#include "sim/fluid/particle_reseeding.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/task_arena.h>

#include <map>

#include "support/cube_grid.h"

namespace fluidsound::sim {
namespace {

constexpr double kCell = 0.01;  // [m]

/// `perCell` particles at fixed spots in every cell, except the cells listed in `counts`.
Particles fill(const GridGeometry& g, int perCell, const std::map<int, int>& counts = {}) {
  Particles p;
  for (int k = 0; k < g.cells[2]; ++k)
    for (int j = 0; j < g.cells[1]; ++j)
      for (int i = 0; i < g.cells[0]; ++i) {
        const int cell = (k * g.cells[1] + j) * g.cells[0] + i;
        const int n = counts.contains(cell) ? counts.at(cell) : perCell;
        for (int q = 0; q < n; ++q) {
          const double f = (q + 0.5) / n;  // spread along the cell diagonal
          const Vec3 x = g.worldFromGrid({i + f, j + f, k + f});
          p.push({float(x[0]), float(x[1]), float(x[2])}, {0.0f, 0.0f, 0.0f});
        }
      }
  return p;
}

std::map<int, int> countPerCell(const Particles& p, const GridGeometry& g) {
  std::map<int, int> counts;
  for (const Vec3f& x : p.position) {
    const Vec3 c = g.gridFromWorld({x[0], x[1], x[2]});
    ++counts[(int(c[2]) * g.cells[1] + int(c[1])) * g.cells[0] + int(c[0])];
  }
  return counts;
}

struct Fixture {
  GridGeometry grid = test::cubeGrid(4, kCell);
  Array3f liquidPhi{grid.cells, float(-kCell)};  // all liquid, a cell deep
  Array3f solidNodes{grid.nodeCount(), 1.0f};    // no solid
  SolidMeshRays noMeshes;
  MacVelocity velocity{grid};

  ReseedingCount reseed(Particles& p, std::uint64_t pass = 1) {
    const CellIndex index = sortParticlesByCell(p, grid);
    SolidBoundary solids;
    solids.grid = grid;
    solids.nodeDistance = solidNodes;
    solids.meshes = &noMeshes;
    return reseedParticles(p, index, liquidPhi, velocity, solids,
                           ReseedingPass{ReseedingLimits{}, 7, pass, 0.0});
  }
};

// Claim: a liquid cell holding fewer than 4 particles is refilled to 8; cells holding 4–16 are
// left alone (counts are exact: this is bookkeeping, not physics).
TEST(ParticleReseeding, RefillsThinLiquidCellsToTheSeedingDensity) {
  Fixture f;
  Particles p = fill(f.grid, 8, {{21, 2}, {42, 0}, {5, 4}});
  const ReseedingCount count = f.reseed(p);
  EXPECT_EQ(count.added, 6u + 8u);
  EXPECT_EQ(count.removed, 0u);
  const auto counts = countPerCell(p, f.grid);
  EXPECT_EQ(counts.at(21), 8);
  EXPECT_EQ(counts.at(42), 8);
  EXPECT_EQ(counts.at(5), 4) << "4 is enough: not refilled";
  EXPECT_EQ(p.size(), 64u * 8u - 4u);
}

// Claim: a clump of more than 16 particles in a cell is thinned to 16.
TEST(ParticleReseeding, ThinsClumpsToSixteen) {
  Fixture f;
  Particles p = fill(f.grid, 8, {{10, 40}, {11, 16}});
  const ReseedingCount count = f.reseed(p);
  EXPECT_EQ(count.removed, 24u);
  EXPECT_EQ(count.added, 0u);
  const auto counts = countPerCell(p, f.grid);
  EXPECT_EQ(counts.at(10), 16);
  EXPECT_EQ(counts.at(11), 16);
}

// Claim: cells that are not wholly liquid (φ > −h/2 at the centre: surface cells, air) and spots
// inside solids get no particle: reseeding must not create liquid.
TEST(ParticleReseeding, NeverFillsAirSurfaceCellsOrSolids) {
  Fixture f;
  f.liquidPhi(1, 0, 0) = float(-0.4 * kCell);  // a surface cell
  f.liquidPhi(2, 0, 0) = float(kCell);         // air
  for (int k = 0; k <= 4; ++k)                 // solid where x < 1.5 cells (nodes i ≤ 1 inside)
    for (int j = 0; j <= 4; ++j)
      for (int i = 0; i <= 4; ++i) f.solidNodes(i, j, k) = float((i - 1.5) * kCell);
  Particles p = fill(f.grid, 8, {{1, 0}, {2, 0}, {0, 0}, {3, 0}});
  f.reseed(p);
  const auto counts = countPerCell(p, f.grid);
  EXPECT_FALSE(counts.contains(1));
  EXPECT_FALSE(counts.contains(2));
  EXPECT_FALSE(counts.contains(0)) << "cell 0 is inside the solid";
  EXPECT_EQ(counts.at(3), 8) << "cell 3 is liquid and clear of the solid";
}

// Claim: new particles carry the grid velocity at their position (here uniform, so exactly it).
TEST(ParticleReseeding, NewParticlesTakeTheGridVelocity) {
  Fixture f;
  for (int a = 0; a < 3; ++a)
    for (float& u : f.velocity[a].values()) u = float(a + 1);
  Particles p = fill(f.grid, 8, {{21, 0}});
  f.reseed(p);
  int fresh = 0;
  for (std::size_t q = 0; q < p.size(); ++q)
    if (p.velocity[q][0] != 0.0f) {
      ++fresh;
      EXPECT_FLOAT_EQ(p.velocity[q][0], 1.0f);
      EXPECT_FLOAT_EQ(p.velocity[q][1], 2.0f);
      EXPECT_FLOAT_EQ(p.velocity[q][2], 3.0f);
    }
  EXPECT_EQ(fresh, 8);
}

// Determinism (brief): the same pass gives the same particles on 1 and 2 threads; another pass
// draws other positions.
TEST(ParticleReseeding, SameParticlesForAnyThreadCountAndNewSpotsEachPass) {
  const auto run = [](int threads, std::uint64_t pass) {
    Particles p;
    oneapi::tbb::task_arena(threads).execute([&] {
      Fixture f;
      p = fill(f.grid, 8, {{21, 1}, {22, 0}, {50, 3}, {60, 30}});
      f.reseed(p, pass);
    });
    return p.position;
  };
  EXPECT_EQ(run(1, 1), run(2, 1));
  EXPECT_NE(run(1, 1), run(1, 2));
}

}  // namespace
}  // namespace fluidsound::sim
