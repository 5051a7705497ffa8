// tests/sim/bubbles/liquid_distance_test.cpp — the distance to the free surface rebuilt from the solver's
// liquid field: exact for a flat surface even from a field that is a distance only near the
// surface (as the solver's is), within a fraction of a cell for a tilted plane and a sphere,
// exact beyond the band through the nearest-surface-point query, blind to solids, and the same
// from one object rebuilt again and again (its memory reused) as from a new one.
#include "sim/bubbles/liquid_distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <numbers>
#include <vector>

#include "support/solver_like_field.h"

namespace fluidsound::sim {
namespace {

using test::solverLikeField;

constexpr int kCells = 32;
constexpr double kCell = 0.005;  // h [m]

GridGeometry cube() {
  GridGeometry g;
  g.cells = {kCells, kCells, kCells};
  g.cellSize = kCell;
  return g;
}

Array3f openNodes(const GridGeometry& g, float value = 1.0f) {
  return Array3f(g.nodeCount(), value);
}

/// The signed distance to a sphere of liquid, centre c and radius r [m].
auto liquidSphere(const Vec3& c, double r) {
  return [c, r](const Vec3& x) { return std::hypot(x[0] - c[0], x[1] - c[1], x[2] - c[2]) - r; };
}

/// A band wider than the grid: the field is the distance everywhere.
constexpr double kWholeGrid = 1.0;  // [m]

/// Largest |d − exact| over all cells [m].
double worstError(const Array3f& d, const GridGeometry& g,
                  const std::function<double(const Vec3&)>& exact) {
  double worst = 0.0;
  for (int k = 0; k < kCells; ++k)
    for (int j = 0; j < kCells; ++j)
      for (int i = 0; i < kCells; ++i)
        worst = std::max(worst, std::abs(d(i, j, k) - exact(g.cellCentre(i, j, k))));
  return worst;
}

TEST(LiquidDistance, FlatSurfaceIsExactEvenFromANearSurfaceField) {
  // Claim: for a horizontal surface, 0.3 h above a row of centres, the redistanced field is the
  // exact y − s at every cell, 20 cells deep, although the input is a distance only within 0.4 h
  // below the surface. Reference: y − s. Tolerance: 3.2e-5 h = 1.6e-7 m, ten times the float
  // rounding of values up to 0.16 m (the crossing and the axis-aligned Godunov update are exact
  // in exact arithmetic).
  const GridGeometry g = cube();
  const double s = g.cellCentre(0, 20, 0)[1] + 0.3 * kCell;
  const auto exact = [&](const Vec3& x) { return x[1] - s; };
  const Array3f d = SurfaceDistance(solverLikeField(g, exact), openNodes(g), g, kWholeGrid).field();
  const double worst = worstError(d, g, exact);
  std::cout << "[ measured ] flat: worst error " << worst / kCell << " h\n";
  EXPECT_LT(worst, 1e-6 * kCell * 32);
}

TEST(LiquidDistance, TiltedPlaneAndSphereAreAccurateToAFractionOfACell) {
  // Claim: for a plane tilted 30° and a sphere of liquid (radius 10 h), from the same clamped
  // field, the redistanced distance is within half a cell of the exact one everywhere, and within
  // a tenth of a cell in root mean square. Reference: the exact distances (for the plane, at
  // cells whose foot point lies inside the grid: distances are to surface points in the grid).
  // Tolerance: 0.5 h maximum — the grid places the surface only to a fraction of a cell; the
  // first layer's plane through the axis crossings errs by O(h) on a curved or oblique surface
  // (measured: 0.38 h for the sphere, 0.13 h for the plane) — and 0.1 h RMS (measured ≤ 0.06 h).
  const GridGeometry g = cube();
  const double angle = std::numbers::pi / 6.0;
  const Vec3 n{std::sin(angle), std::cos(angle), 0.0};
  const auto plane = [&](const Vec3& x) { return n[0] * x[0] + n[1] * x[1] + n[2] * x[2] - 0.08; };
  const auto footInGrid = [&](const Vec3& x) {
    const double d = plane(x), extent = kCells * kCell;
    const Vec3 foot{x[0] - d * n[0], x[1] - d * n[1], x[2]};
    for (double f : foot)
      if (f < kCell || f > extent - kCell) return false;
    return true;
  };
  const auto sphere = liquidSphere({0.08, 0.08, 0.08}, 10 * kCell);
  for (int shape = 0; shape < 2; ++shape) {
    const std::function<double(const Vec3&)> exact =
        shape == 0 ? std::function<double(const Vec3&)>(plane) : sphere;
    const Array3f d = SurfaceDistance(solverLikeField(g, exact), openNodes(g), g, kWholeGrid).field();
    double worst = 0.0, squares = 0.0;
    int count = 0;
    for (int k = 0; k < kCells; ++k)
      for (int j = 0; j < kCells; ++j)
        for (int i = 0; i < kCells; ++i) {
          const Vec3 x = g.cellCentre(i, j, k);
          if (shape == 0 && !footInGrid(x)) continue;
          const double e = std::abs(d(i, j, k) - exact(x));
          worst = std::max(worst, e), squares += e * e, ++count;
        }
    const double rms = std::sqrt(squares / count);
    std::cout << "[ measured ] " << (shape == 0 ? "tilted plane" : "sphere") << ": worst "
              << worst / kCell << " h, rms " << rms / kCell << " h over " << count << " cells\n";
    EXPECT_LT(worst, 0.5 * kCell);
    EXPECT_LT(rms, 0.1 * kCell);
  }
}

TEST(LiquidDistance, SolidsMakeNoSurface) {
  // Claim: a solid block under the surface, whose cells hold no particles (the solver's φ is
  // positive, "air", there), makes no surface: the depth above, beside and beneath it is still
  // the distance to the free surface (distances pass through solid cells). Reference: y − s at
  // every cell outside the block. Tolerance: as for a flat surface (the same axis-aligned problem).
  const GridGeometry g = cube();
  const double s = g.cellCentre(0, 24, 0)[1] + 0.3 * kCell;  // both straddling values unclamped
  const auto inBlock = [&](const Vec3& x) {
    return x[0] > 0.04 && x[0] < 0.08 && x[1] > 0.02 && x[1] < 0.06 && x[2] > 0.04 && x[2] < 0.08;
  };
  Array3f phi = solverLikeField(g, [&](const Vec3& x) { return x[1] - s; });
  for (int k = 0; k < kCells; ++k)
    for (int j = 0; j < kCells; ++j)
      for (int i = 0; i < kCells; ++i)
        if (inBlock(g.cellCentre(i, j, k)))
          phi(i, j, k) = static_cast<float>(1.5 * kCell);  // "air"
  Array3f nodes(g.nodeCount());
  for (int k = 0; k <= kCells; ++k)
    for (int j = 0; j <= kCells; ++j)
      for (int i = 0; i <= kCells; ++i) {
        const Vec3 x = g.worldFromGrid({1.0 * i, 1.0 * j, 1.0 * k});
        // Distance to the block, negative inside (exact enough for the sign, which is all it sets).
        const double dx = std::max(0.04 - x[0], x[0] - 0.08),
                     dy = std::max(0.02 - x[1], x[1] - 0.06),
                     dz = std::max(0.04 - x[2], x[2] - 0.08);
        nodes(i, j, k) = static_cast<float>(std::max({dx, dy, dz}));
      }
  const Array3f d = SurfaceDistance(phi, nodes, g, kWholeGrid).field();
  double worst = 0.0;
  for (int k = 0; k < kCells; ++k)
    for (int j = 0; j < kCells; ++j)
      for (int i = 0; i < kCells; ++i) {
        const Vec3 x = g.cellCentre(i, j, k);
        if (!inBlock(x)) worst = std::max(worst, std::abs(d(i, j, k) - (x[1] - s)));
      }
  std::cout << "[ measured ] beside a block: worst error " << worst / kCell << " h\n";
  EXPECT_LT(worst, 1e-6 * kCell * 32);
}

TEST(LiquidDistance, BeyondTheBandTheNearestSurfacePointGivesTheDepth) {
  // Claim: with a band of 4 cells, the grid field holds −4 h below it, and at() still returns the
  // distance to the surface anywhere, down to 20 cells deep, at arbitrary positions. Reference:
  // for a flat surface y − s, for the sphere |x − c| − R (exact). Tolerance: flat h/8 — beyond
  // band − 2 h = 2 h at() measures to the nearest surface point, and the points lie one per cell
  // column, so a position off the columns by up to h/√2 errs by √(D² + h²/2) − D ≤ h²/(4D) ≤ h/8
  // at D ≥ 2 h (the model's band puts the switch ≥ 4 h deep: ≤ h/16); sphere 0.5 h as in the band.
  const GridGeometry g = cube();
  const double band = 4 * kCell;
  const double s = g.cellCentre(0, 24, 0)[1] + 0.3 * kCell;
  const auto flat = [&](const Vec3& x) { return x[1] - s; };
  const SurfaceDistance flatDistance(solverLikeField(g, flat), openNodes(g), g, band);
  EXPECT_FLOAT_EQ(flatDistance.field()(10, 2, 10), static_cast<float>(-band));
  const auto sphere = liquidSphere({0.08, 0.08, 0.08}, 10 * kCell);
  const SurfaceDistance sphereDistance(solverLikeField(g, sphere), openNodes(g), g, band);
  double worstFlat = 0.0, worstSphere = 0.0;
  for (int n = 0; n < 2000; ++n) {  // a fixed quasi-random set of positions (golden-ratio steps)
    const Vec3 x{0.16 * std::fmod(0.5 + n * 0.6180339887, 1.0),
                 0.16 * std::fmod(0.5 + n * 0.7548776662, 1.0),
                 0.16 * std::fmod(0.5 + n * 0.5698402910, 1.0)};
    if (flat(x) < -2 * kCell)
      worstFlat = std::max(worstFlat, std::abs(flatDistance.at(x) - flat(x)));
    worstSphere = std::max(worstSphere, std::abs(sphereDistance.at(x) - sphere(x)));
  }
  std::cout << "[ measured ] beyond the band: worst error flat " << worstFlat / kCell
            << " h, sphere " << worstSphere / kCell << " h\n";
  EXPECT_LT(worstFlat, 0.125 * kCell);
  EXPECT_LT(worstSphere, 0.5 * kCell);
}

TEST(LiquidDistance, ANarrowerAirBandClampsOnlyTheAirSide) {
  // Claim: an air band narrower than the liquid band (the bubble model reads only the tagging band
  // above the surface) leaves every value within it unchanged — the liquid side, and the air side
  // up to airBand — and holds +airBand beyond; rebuilding an object gives what a new one gives.
  // Reference: the same field with both bands equal, for a sphere of liquid (curved, so points
  // reach cells along oblique paths). Tolerance: exact (the same nearest points, cut further out).
  const GridGeometry g = cube();
  const auto sphere = liquidSphere({0.08, 0.08, 0.08}, 10 * kCell);
  const Array3f phi = solverLikeField(g, sphere);
  const double band = 6 * kCell, airBand = 3 * kCell;
  const Array3f both = SurfaceDistance(phi, openNodes(g), g, band).field();
  SurfaceDistance narrow(solverLikeField(g, [](const Vec3&) { return 1.0; }), openNodes(g), g, band);
  narrow.rebuild(phi, openNodes(g), g, band, airBand);
  int compared = 0;
  for (std::size_t at = 0; at < both.elementCount(); ++at) {
    const float expected =
        both.data()[at] < airBand ? both.data()[at] : static_cast<float>(airBand);
    ASSERT_EQ(narrow.field().data()[at], expected) << "cell " << at;
    compared += both.data()[at] < 0.0f;
  }
  EXPECT_GT(compared, 1000);
}

TEST(LiquidDistance, BandCellsHoldTheDistanceToTheNearestSurfacePoint) {
  // Claim: within its side's band every cell not next to the surface holds the distance to the
  // nearest of all surface points (not only to one its neighbours pass on), beyond it ±band, and a
  // cell next to the surface the distance to its own point (no nearer than the nearest). Reference:
  // the minimum over surfacePoints() by brute force, for a sphere of liquid (curved, so the nearest
  // point of a cell is seldom its neighbour's). Tolerance: 1e-6 h, the float arithmetic of the
  // squared distance (three roundings, ≤ 1.8e-7 relative, so ≤ 0.9e-7 relative in the distance)
  // and of the stored value (6e-8 relative), at most 4.75 h: ≤ 7e-7 h.
  const GridGeometry g = cube();
  const auto sphere = liquidSphere({0.081, 0.078, 0.0805}, 9.3 * kCell);
  const Array3f phi = solverLikeField(g, sphere);
  const double band = 4.75 * kCell, airBand = 2.75 * kCell;
  const SurfaceDistance distance(phi, openNodes(g), g, band, airBand);
  const std::vector<Vec3>& points = distance.surfacePoints();
  ASSERT_GT(points.size(), 1000u);
  const auto liquid = [&](int i, int j, int k) { return phi(i, j, k) < 0.0f; };
  int inBand = 0;
  double worst = 0.0;
  for (int k = 0; k < kCells; ++k)
    for (int j = 0; j < kCells; ++j)
      for (int i = 0; i < kCells; ++i) {
        const Vec3 x = g.cellCentre(i, j, k);
        double nearest = 1e9;
        for (const Vec3& p : points)
          nearest = std::min(nearest, std::hypot(x[0] - p[0], x[1] - p[1], x[2] - p[2]));
        const double side = liquid(i, j, k) ? band : airBand;
        const double expected = std::min(nearest, side);
        const double got = std::abs(distance.field()(i, j, k));
        ASSERT_EQ(distance.field()(i, j, k) < 0.0f, liquid(i, j, k)) << i << " " << j << " " << k;
        bool nextToSurface = false;
        for (int a = 0; a < 3; ++a)
          for (int step : {-1, 1}) {
            Index3 n{i, j, k};
            n[a] += step;
            if (n[a] >= 0 && n[a] < kCells && liquid(n[0], n[1], n[2]) != liquid(i, j, k))
              nextToSurface = true;
          }
        if (nextToSurface) {
          EXPECT_GE(got, expected * (1.0 - 1e-6)) << i << " " << j << " " << k;
          continue;
        }
        worst = std::max(worst, std::abs(got - expected));
        inBand += nearest < side;
      }
  std::cout << "[ measured ] " << inBand << " band cells: worst |field − nearest point| "
            << worst / kCell << " h\n";
  EXPECT_GT(inBand, 5000);
  EXPECT_LT(worst, 1e-6 * kCell);
}

TEST(LiquidDistance, NoSurfaceGivesTheBandOnTheGridAndTheDiagonalAnywhere) {
  // Claim: a grid all liquid (or all air) has no surface: the field is ∓band everywhere and at()
  // returns ∓ the grid's diagonal.
  const GridGeometry g = cube();
  const double diagonal = kCell * kCells * std::sqrt(3.0), band = 4 * kCell;
  const SurfaceDistance allLiquid(Array3f(g.cells, -0.001f), openNodes(g), g, band);
  const SurfaceDistance allAir(Array3f(g.cells, 0.001f), openNodes(g), g, band);
  EXPECT_FLOAT_EQ(allLiquid.field()(3, 4, 5), static_cast<float>(-band));
  EXPECT_FLOAT_EQ(allAir.field()(3, 4, 5), static_cast<float>(band));
  EXPECT_DOUBLE_EQ(allLiquid.at({0.05, 0.05, 0.05}), -diagonal);
  EXPECT_DOUBLE_EQ(allAir.at({0.05, 0.05, 0.05}), diagonal);
  EXPECT_TRUE(allLiquid.surfacePoints().empty());
}

}  // namespace
}  // namespace fluidsound::sim

namespace fluidsound::sim {
namespace {

TEST(LiquidDistance, RebuildingOneObjectGivesWhatAFreshOneGives) {
  // Claim: a SurfaceDistance rebuilt again and again (the bubble model's use, which keeps its work
  // arrays and its solid cells between rebuilds) gives exactly what a new object gives, whatever
  // it held before: a moved solid, another grid size, another band. Reference: a freshly
  // constructed SurfaceDistance on the same input. Tolerance: none (the same arithmetic).
  const auto blockNodes = [](const GridGeometry& g, double x0) {
    Array3f nodes(g.nodeCount());
    for (int k = 0; k <= g.cells[2]; ++k)
      for (int j = 0; j <= g.cells[1]; ++j)
        for (int i = 0; i <= g.cells[0]; ++i) {
          const Vec3 x = g.worldFromGrid({1.0 * i, 1.0 * j, 1.0 * k});
          const double dx = std::max(x0 - x[0], x[0] - (x0 + 0.03)),
                       dy = std::max(0.01 - x[1], x[1] - 0.04),
                       dz = std::max(0.03 - x[2], x[2] - 0.07);
          nodes(i, j, k) = static_cast<float>(std::max({dx, dy, dz}));
        }
    return nodes;
  };
  const GridGeometry a = cube();
  GridGeometry b;
  b.cells = {20, 28, 12};
  b.cellSize = kCell;
  b.origin = {0.01, -0.02, 0.0};
  const auto sphere = [](const Vec3& x) {
    return std::hypot(x[0] - 0.07, x[1] - 0.06, x[2] - 0.08) - 0.035;  // a drop
  };
  const auto tilted = [](const Vec3& x) { return 0.6 * x[0] + 0.8 * x[1] - 0.06; };
  struct Input {
    const GridGeometry* grid;
    Array3f phi, nodes;
    double band, airBand;
  };
  const std::vector<Input> inputs = {
      {&a, solverLikeField(a, sphere), openNodes(a), 6 * kCell, 4 * kCell},
      {&a, solverLikeField(a, sphere), blockNodes(a, 0.05), 6 * kCell, 4 * kCell},
      {&a, solverLikeField(a, tilted), blockNodes(a, 0.08), 6 * kCell, 4 * kCell},
      {&b, solverLikeField(b, tilted), openNodes(b), 5 * kCell, 0.0},
      {&a, solverLikeField(a, sphere), blockNodes(a, 0.05), 9 * kCell, 2 * kCell},
  };
  SurfaceDistance reused;
  for (std::size_t n = 0; n < inputs.size(); ++n) {
    const Input& in = inputs[n];
    reused.rebuild(in.phi, in.nodes, *in.grid, in.band, in.airBand);
    const SurfaceDistance fresh(in.phi, in.nodes, *in.grid, in.band, in.airBand);
    EXPECT_EQ(reused.field().values(), fresh.field().values()) << "rebuild " << n;
    EXPECT_EQ(reused.surfacePoints(), fresh.surfacePoints()) << "rebuild " << n;
    const Vec3 deep = in.grid->cellCentre(in.grid->cells[0] / 2, 1, in.grid->cells[2] / 2);
    EXPECT_EQ(reused.at(deep), fresh.at(deep)) << "rebuild " << n;
  }
}

}  // namespace
}  // namespace fluidsound::sim
