// Tests of sim/fluid/liquid_level_set.h: the grid level set the pressure solve sees — its start from
// the scene's regions, its hold to the particle surface, its advection, its volume shift and its
// continuation through static solids. Small synthetic grids; each claim is exact arithmetic or
// a bound the method sets itself.
#include "sim/fluid/liquid_level_set.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/fluid/liquid_surface.h"
#include "sim/fluid/solid_geometry.h"

namespace fluidsound::sim {
namespace {

constexpr double kCell = 0.01;  // [m]
constexpr double kLevel = 0.0735;

/// A closed 16³ box of 1 cm cells, water to 7.35 cm, and optionally a sphere solid in it.
FluidScene tank(bool withSphere = false) {
  FluidScene s;
  s.domain.max = {0.16, 0.16, 0.16};
  s.domain.cell = kCell;
  s.liquid.push_back({Box{{0, 0, 0}, {0.16, kLevel, 0.16}}, {}});
  if (withSphere) {
    Solid sphere;
    sphere.shape = Sphere{{0.08, 0.04, 0.08}, 0.025};
    s.solids.push_back(sphere);
  }
  return s;
}

Array3f nodesOf(const FluidScene& s, bool walls) {
  Domain d = s.domain;
  if (!walls) d.open.fill(true);
  return solidNodeDistance(s.grid(), d, s.solids, 0.0);
}

/// Calls f(i, j, k, centre) for every cell of the grid, in index order.
template <class F>
void forEachCell(const GridGeometry& g, F f) {
  for (int k = 0; k < g.cells[2]; ++k)
    for (int j = 0; j < g.cells[1]; ++j)
      for (int i = 0; i < g.cells[0]; ++i) f(i, j, k, g.cellCentre(i, j, k));
}

/// A cell index with `count` particles in every cell (the positions do not matter to the hold).
CellIndex uniformIndex(const Index3& n, std::size_t count) {
  CellIndex index;
  const std::size_t cells = static_cast<std::size_t>(n[0]) * n[1] * n[2];
  index.start.resize(cells + 1);
  for (std::size_t c = 0; c <= cells; ++c) index.start[c] = c * count;
  return index;
}

// Claim: a box region's faces on the domain walls are no surface — the start level is y − H in
// every cell, the wall columns included (the box's own distance would read half a cell deep
// there) — and the inside of a solid is air. Reference: y − H, exact up to float rounding.
TEST(LiquidLevelSet, StartsAtTheRegionsFreeSurfaceAndAirInSolids) {
  const FluidScene scene = tank(true);
  const GridGeometry g = scene.grid();
  const LiquidLevelSet level(scene, g, nodesOf(scene, true));
  int inSphere = 0;
  forEachCell(g, [&](int i, int j, int k, const Vec3& x) {
    const double sphere = std::hypot(x[0] - 0.08, x[1] - 0.04, x[2] - 0.08) - 0.025;
    if (sphere < -0.25 * kCell) {
      EXPECT_GT(level.phi()(i, j, k), 0.0f) << i << " " << j << " " << k;
      ++inSphere;
    } else if (sphere > 0.25 * kCell && x[1] - kLevel < 8 * kCell) {
      EXPECT_NEAR(level.phi()(i, j, k), x[1] - kLevel, 1e-6) << i << " " << j << " " << k;
    }
  });
  EXPECT_GT(inSphere, 20);
}

// Claim: a box region's faces lying against a scene solid are no surface either. Water filled
// up to a wall off the cell planes (a box solid x < 31.7 mm, the water box starting there) and
// into a second wall it overlaps (z > 123.3 mm, the water box reaching 140 mm) starts at y − H in
// every cell outside the walls, the cells those walls cut included (the box's own distance
// would read the cells beside x = 31.7 mm 0.17 cell deep: a slope the pressure solve turns into
// a flow). A face with its foot point clear of every solid still counts: without the walls the
// same box reads its own distance. Reference: y − H and the box's distance, exact up to float.
TEST(LiquidLevelSet, ARegionsFacesAgainstASolidAreNoSurface) {
  FluidScene scene = tank();
  const double wallX = 0.0317, wallZ = 0.1233;
  scene.liquid[0].shape = Box{{wallX, 0, 0}, {0.16, kLevel, 0.14}};
  Solid left, back;
  left.shape = Box{{-0.01, -0.01, -0.01}, {wallX, 0.17, 0.17}};
  back.shape = Box{{-0.01, -0.01, wallZ}, {0.17, 0.17, 0.17}};
  scene.solids = {left, back};
  const GridGeometry g = scene.grid();
  const LiquidLevelSet level(scene, g, nodesOf(scene, true));
  int checked = 0;
  forEachCell(g, [&](int i, int j, int k, const Vec3& x) {
    if (x[0] < wallX || x[2] > wallZ || x[1] - kLevel > 3 * kCell) return;
    EXPECT_NEAR(level.phi()(i, j, k), x[1] - kLevel, 1e-6) << i << " " << j << " " << k;
    ++checked;
  });
  EXPECT_EQ(checked, 13 * 12 * 10);  // columns i = 3 … 15, k = 0 … 11; rows j = 0 … 9
  scene.solids.clear();
  const LiquidLevelSet free(scene, g, nodesOf(scene, true));
  const Vec3 beside = g.cellCentre(3, 5, 5);  // 3.3 mm from the face x = 31.7 mm, 18.5 mm deep
  EXPECT_NEAR(free.phi()(3, 5, 5), -(beside[0] - wallX), 1e-6);
}

// Claim: a box region's faces on the grid's boundary are no surface whether the domain face is
// a closed wall or open (the liquid runs on through an open face; only a closed wall has a solid
// distance to test): with every face open the start level is still y − H in every column.
// Reference: y − H, exact up to float rounding.
TEST(LiquidLevelSet, ABoxsFacesOnOpenDomainFacesAreNoSurface) {
  FluidScene scene = tank();
  scene.domain.open.fill(true);
  const GridGeometry g = scene.grid();
  const LiquidLevelSet level(scene, g, nodesOf(scene, true));
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 11; ++j)
      for (int i = 0; i < 16; ++i)
        EXPECT_NEAR(level.phi()(i, j, k), g.cellCentre(i, j, k)[1] - kLevel, 1e-6)
            << i << " " << j << " " << k;
}

// Claim: in still liquid (zero velocity) the hold moves φ only where it leaves the band of
// ±bandCells around the particle surface, and then onto its edge; at the trust speed and above
// the band is 0 and φ is the particle surface. Cells with a particle or two around and none full
// (one particle per cell here) are the ones the band governs. Reference: the clamp, exact.
TEST(LiquidLevelSet, HoldsWithinTheBandInStillLiquidAndFollowsFastLiquid) {
  const FluidScene scene = tank();
  const GridGeometry g = scene.grid();
  const Array3f noSolid = nodesOf(scene, false);
  const CellIndex onePerCell = uniformIndex(g.cells, 1);
  const LevelSetHold hold;  // 1 cell, 0.1 m/s, 4 per cell full
  for (const double offsetCells : {0.6, 1.7, -2.5}) {
    SCOPED_TRACE(offsetCells);
    LiquidLevelSet level(scene, g, nodesOf(scene, true));
    const Array3f before = level.phi();
    Array3f particle = before;
    for (float& v : particle.values()) v = static_cast<float>(v + offsetCells * kCell);
    MacVelocity still(g);
    level.holdToParticles(particle, onePerCell, still, noSolid, hold);
    const double moved =
        std::max(0.0, std::abs(offsetCells) - hold.bandCells) * (offsetCells > 0 ? 1 : -1);
    for (std::size_t c = 0; c < before.values().size(); ++c)
      ASSERT_NEAR(level.phi().values()[c], before.values()[c] + moved * kCell, 1e-6) << c;
    MacVelocity fast(g);
    for (float& u : fast[0].values()) u = static_cast<float>(hold.trustSpeed);
    level.holdToParticles(particle, onePerCell, fast, noSolid, hold);
    for (std::size_t c = 0; c < before.values().size(); ++c)
      ASSERT_EQ(level.phi().values()[c], particle.values()[c]);
  }
}

// Claim: where the particles leave no doubt the band does not apply: every cell around full
// (≥ half the seeding count) is liquid at least half a cell deep, no particle around is air at
// least half a cell up (to float rounding). Cells on the grid's faces have cells beyond the grid
// around them, which hold nothing: never full. Reference: ∓h/2.
TEST(LiquidLevelSet, FollowsTheParticlesWhereTheyLeaveNoDoubt) {
  const FluidScene scene = tank();
  const GridGeometry g = scene.grid();
  const Array3f noSolid = nodesOf(scene, false);
  MacVelocity still(g);
  LiquidLevelSet full(scene, g, nodesOf(scene, true));
  const Array3f air(g.cells, static_cast<float>(5 * kCell));
  full.holdToParticles(air, uniformIndex(g.cells, 8), still, noSolid, LevelSetHold{});
  for (int k = 1; k < 15; ++k)
    for (int j = 1; j < 15; ++j)
      for (int i = 1; i < 15; ++i)
        ASSERT_LE(full.phi()(i, j, k), -0.5 * kCell + 1e-7) << i << " " << j << " " << k;
  LiquidLevelSet empty(scene, g, nodesOf(scene, true));
  const Array3f liquid(g.cells, static_cast<float>(-5 * kCell));
  empty.holdToParticles(liquid, uniformIndex(g.cells, 0), still, noSolid, LevelSetHold{});
  for (const float v : empty.phi().values()) ASSERT_GE(v, 0.5 * kCell - 1e-7);
}

// Claim: advection carries a level with the liquid: a uniform flow u moves the plane φ = y − H by
// u·Δt (semi-Lagrangian, RK2: exact for a uniform velocity and a linear φ, whose trilinear
// interpolation is exact) within the advected band (4 cells here), and leaves φ beyond it.
// Reference: y − H − u_y Δt, to float rounding.
TEST(LiquidLevelSet, AdvectionMovesAPlaneWithAUniformFlow) {
  const FluidScene scene = tank();
  const GridGeometry g = scene.grid();
  LiquidLevelSet level(scene, g, nodesOf(scene, true));
  MacVelocity u(g);
  const double up = 0.2, dt = 0.01;  // 2 mm up
  for (float& v : u[1].values()) v = static_cast<float>(up);
  const Array3f before = level.phi();
  level.advect(u, nodesOf(scene, false), dt, 4.0);
  int advected = 0;
  for (int k = 1; k < 15; ++k)
    for (int j = 1; j < 14; ++j)
      for (int i = 1; i < 15; ++i) {
        const double plane = g.cellCentre(i, j, k)[1] - kLevel;
        if (std::abs(before(i, j, k)) < 4.0 * kCell) {
          ASSERT_NEAR(level.phi()(i, j, k), plane - up * dt, 1e-6) << i << " " << j << " " << k;
          ++advected;
        } else {
          ASSERT_EQ(level.phi()(i, j, k), before(i, j, k));
        }
      }
  EXPECT_EQ(advected, 14 * 8 * 14);  // rows 4 … 11: centres within 4 cells of the surface
}

// Claim: matchVolume shifts φ by one constant so that the volume it describes is the target: a
// flat level asked for 2 mm more water over the 16 × 16 cm tank rises 2 mm everywhere.
// Reference: V + A·2 mm, to 1e-4 relative (the volume's 4³ samples per cell resolve a shift of a
// fifth of a cell exactly for a plane), and the same shift in every cell.
TEST(LiquidLevelSet, MatchVolumeShiftsTheLevelToTheTarget) {
  const FluidScene scene = tank();
  const GridGeometry g = scene.grid();
  const Array3f noSolid = nodesOf(scene, false);
  LiquidLevelSet level(scene, g, nodesOf(scene, true));
  const Array3f before = level.phi();
  const double volume = liquidVolumeOutsideSolids(before, noSolid, g);
  const double target = volume + 0.16 * 0.16 * 0.002;
  level.matchVolume(target, noSolid);
  EXPECT_NEAR(liquidVolumeOutsideSolids(level.phi(), noSolid, g), target, 1e-4 * target);
  const double shift = level.phi()(0, 0, 0) - before(0, 0, 0);
  EXPECT_NEAR(shift, -0.002, 1e-4);
  for (std::size_t c = 0; c < before.values().size(); ++c)
    ASSERT_NEAR(level.phi().values()[c] - before.values()[c], shift, 1e-6);
}

// Claim: for the pressure solve a flat level runs on through a static solid: a cell whose centre
// is inside the solid takes its horizontal neighbours' φ (or the one above, one cell deeper), so
// for φ = y − H it holds y − H too; cells outside the solid keep theirs. Reference: y − H.
TEST(LiquidLevelSet, ALevelRunsOnThroughASolidAtItsOwnHeight) {
  const FluidScene scene = tank(true);
  const GridGeometry g = scene.grid();
  Array3f flat(g.cells);
  forEachCell(g, [&](int i, int j, int k, const Vec3& x) {
    flat(i, j, k) = static_cast<float>(x[1] - kLevel);
  });
  const Array3f extended = extendLevelAcrossSolids(flat, nodesOf(scene, true), {0, 1, 0}, kCell);
  for (std::size_t c = 0; c < flat.values().size(); ++c)
    ASSERT_NEAR(extended.values()[c], flat.values()[c], 1e-6);
  // Another height inside the sphere is replaced wherever a horizontal neighbour or the cell above
  // lies outside it: the sphere's outer cells. Its core keeps what it had.
  const auto inSphere = [&](int i, int j, int k) {
    const Vec3 x = g.cellCentre(i, j, k);
    return std::hypot(x[0] - 0.08, x[1] - 0.04, x[2] - 0.08) - 0.025;
  };
  Array3f wrong = flat;
  forEachCell(g, [&](int i, int j, int k, const Vec3&) {
    if (inSphere(i, j, k) < -0.3 * kCell) wrong(i, j, k) = 1.0f;
  });
  const Array3f healed = extendLevelAcrossSolids(wrong, nodesOf(scene, true), {0, 1, 0}, kCell);
  int replaced = 0;
  for (int k = 1; k < 15; ++k)
    for (int j = 1; j < 15; ++j)
      for (int i = 1; i < 15; ++i) {
        if (inSphere(i, j, k) >= -0.3 * kCell) continue;
        const bool outsideNeighbour =
            inSphere(i - 1, j, k) > 0.3 * kCell || inSphere(i + 1, j, k) > 0.3 * kCell ||
            inSphere(i, j, k - 1) > 0.3 * kCell || inSphere(i, j, k + 1) > 0.3 * kCell;
        if (!outsideNeighbour) continue;
        EXPECT_NEAR(healed(i, j, k), flat(i, j, k), 1e-6) << i << " " << j << " " << k;
        ++replaced;
      }
  EXPECT_GT(replaced, 8);
}

// Claim: where two walls off the cell planes meet, the corner column's cells have only solid
// cells beside them; the second pass fills them from the cells the first filled, so particles
// stopped in that corner are in liquid for the pressure solve (they fell as if in air: a still
// basin off the planes moved at 0.4–0.7 m/s). Walls x < 13.7 mm and z > 146.3 mm of the 16 cm
// tank: the cells i = 0 and k = 15 have their centres inside (1.3 mm past a node plane), the
// column (0, j, 15) is inside both. Rows 2 … 13 (the closed floor's and ceiling's nodes, at
// distance 0, move the cells of rows 0 and 15 next to a wall across the solid rule). Reference:
// y − H in every cell of those rows, the corner column included.
TEST(LiquidLevelSet, ALevelFillsTheCornerOfTwoWallsOffTheCellPlanes) {
  FluidScene scene = tank();
  Solid wallX, wallZ;
  wallX.shape = Box{{-0.1, -0.1, -0.1}, {0.0137, 0.3, 0.3}};
  wallZ.shape = Box{{-0.1, -0.1, 0.1463}, {0.3, 0.3, 0.3}};
  scene.solids = {wallX, wallZ};
  const GridGeometry g = scene.grid();
  Array3f flat(g.cells), wrong(g.cells);
  forEachCell(g, [&](int i, int j, int k, const Vec3& x) {
    flat(i, j, k) = static_cast<float>(x[1] - kLevel);
    wrong(i, j, k) = (i == 0 || k == 15) ? 1.0f : flat(i, j, k);  // the wall cells read air
  });
  const Array3f healed = extendLevelAcrossSolids(wrong, nodesOf(scene, true), {0, 1, 0}, kCell);
  for (int k = 0; k < 16; ++k)
    for (int j = 2; j < 14; ++j)
      for (int i = 0; i < 16; ++i)
        ASSERT_NEAR(healed(i, j, k), flat(i, j, k), 1e-6) << i << " " << j << " " << k;
}

}  // namespace
}  // namespace fluidsound::sim
