// tests/sim/bubbles/liquid_distance_reference_test.cpp — SurfaceDistance's tuned rebuild (row
// skipping, task planes, float rows, buckets) gives the same bits as the plain reference on a
// sphere, a slab, a splash-like random field and a grid with a solid, for both band widths.
#include "sim/bubbles/liquid_distance_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "sim/bubbles/liquid_distance.h"
#include "support/solver_like_field.h"

namespace fluidsound::sim {
namespace {

using test::solverLikeField;

constexpr double kCell = 0.005;  // h [m]

GridGeometry box(int ni, int nj, int nk, const Vec3& origin = {0.0, 0.0, 0.0}) {
  GridGeometry g;
  g.cells = {ni, nj, nk};
  g.cellSize = kCell;
  g.origin = origin;
  return g;
}

Array3f openNodes(const GridGeometry& g) { return Array3f(g.nodeCount(), 1.0f); }

/// Compares the fast field and points with the reference's, bit for bit; returns the number of
/// cells strictly inside either band (neither a clamp nor a surface cell's own value).
int expectSameBits(const Array3f& phi, const Array3f& nodes, const GridGeometry& g, double band,
                   double airBand) {
  const SurfaceDistance fast(phi, nodes, g, band, airBand);
  const SurfaceDistanceReference plain = surfaceDistanceReference(phi, nodes, g, band, airBand);
  const std::vector<float>& a = fast.field().values();
  const std::vector<float>& b = plain.field.values();
  EXPECT_EQ(a.size(), b.size());
  int differing = 0, inside = 0;
  const float liquidSide = static_cast<float>(band), airSide = static_cast<float>(airBand);
  for (std::size_t c = 0; c < std::min(a.size(), b.size()); ++c) {
    if (std::bit_cast<std::uint32_t>(a[c]) != std::bit_cast<std::uint32_t>(b[c]) &&
        ++differing <= 5)
      ADD_FAILURE() << "cell " << c << ": fast " << a[c] << ", reference " << b[c];
    inside += std::abs(a[c]) < (a[c] < 0.0f ? liquidSide : airSide) && a[c] != 0.0f;
  }
  EXPECT_EQ(differing, 0);
  const auto byCoordinates = [](const Vec3& p, const Vec3& q) {
    return std::lexicographical_compare(p.begin(), p.end(), q.begin(), q.end());
  };
  std::vector<Vec3> fastPoints = fast.surfacePoints(), plainPoints = plain.points;
  std::sort(fastPoints.begin(), fastPoints.end(), byCoordinates);
  std::sort(plainPoints.begin(), plainPoints.end(), byCoordinates);
  EXPECT_EQ(fastPoints, plainPoints);
  EXPECT_GT(plainPoints.size(), 50u);
  return inside;
}

TEST(LiquidDistanceReference, SphereGivesTheSameBits) {
  // Claim: for a drop of liquid (curved: the nearest point of a cell is seldom its neighbour's),
  // with the bubble model's bands (4.75 h, 2.75 h above), fast and reference agree bit for bit.
  const GridGeometry g = box(24, 24, 24);
  const Array3f phi = solverLikeField(g, [](const Vec3& x) {
    return std::hypot(x[0] - 0.061, x[1] - 0.058, x[2] - 0.0605) - 7.3 * kCell;
  });
  EXPECT_GT(expectSameBits(phi, openNodes(g), g, 4.75 * kCell, 2.75 * kCell), 3000);
}

TEST(LiquidDistanceReference, SlabGivesTheSameBits) {
  // Claim: a tilted slab of liquid (a floor and a surface, each cut by the grid's edges) on a
  // grid that is not a cube, off the origin, with one band for both sides: the same bits.
  const GridGeometry g = box(30, 20, 14, {0.01, -0.02, 0.003});
  const Array3f phi = solverLikeField(g, [](const Vec3& x) {
    const double above = 0.2 * x[0] + 0.95 * x[1] + 0.1 * x[2] - 0.05, below = -x[1];
    return std::max(above, below);
  });
  EXPECT_GT(expectSameBits(phi, openNodes(g), g, 5.2 * kCell, 0.0), 2000);
}

TEST(LiquidDistanceReference, SplashLikeRandomFieldGivesTheSameBits) {
  // Claim: a pool with a rough surface, drops in the air and bubbles of air in the liquid, φ
  // unclamped and noisy (crossings anywhere in the cell, ties and cells with several crossings):
  // the same bits. Random with a fixed seed; any seed must pass.
  const GridGeometry g = box(26, 22, 18);
  std::mt19937_64 random(18);
  const auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(random() >> 11) * 0x1p-53;
  };
  std::vector<Vec3> drops, voids;
  for (int d = 0; d < 12; ++d)
    drops.push_back({uniform(0, 0.13), uniform(0.06, 0.11), uniform(0, 0.09)});
  for (int d = 0; d < 6; ++d)
    voids.push_back({uniform(0, 0.13), uniform(0.0, 0.04), uniform(0, 0.09)});
  Array3f phi(g.cells);
  for (int k = 0; k < g.cells[2]; ++k)
    for (int j = 0; j < g.cells[1]; ++j)
      for (int i = 0; i < g.cells[0]; ++i) {
        const Vec3 x = g.cellCentre(i, j, k);
        double d = x[1] - 0.05 - 0.01 * std::sin(90.0 * x[0]) * std::cos(70.0 * x[2]);
        for (const Vec3& c : drops)
          d = std::min(d, std::hypot(x[0] - c[0], x[1] - c[1], x[2] - c[2]) - 1.6 * kCell);
        for (const Vec3& c : voids)
          d = std::max(d, 1.8 * kCell - std::hypot(x[0] - c[0], x[1] - c[1], x[2] - c[2]));
        phi(i, j, k) = static_cast<float>(d + uniform(-0.3, 0.3) * kCell);
      }
  EXPECT_GT(expectSameBits(phi, openNodes(g), g, 4.75 * kCell, 2.75 * kCell), 3000);
}

TEST(LiquidDistanceReference, GridWithASolidGivesTheSameBits) {
  // Claim: a block of solid across the surface (its cells make no surface; distances pass
  // through them; they count as liquid in the sign) and the grid's walls: the same bits.
  const GridGeometry g = box(24, 24, 20);
  const Array3f phi = solverLikeField(g, [](const Vec3& x) { return 0.4 * x[0] + x[1] - 0.07; });
  Array3f nodes(g.nodeCount());
  for (int k = 0; k <= g.cells[2]; ++k)
    for (int j = 0; j <= g.cells[1]; ++j)
      for (int i = 0; i <= g.cells[0]; ++i) {
        const Vec3 x = g.worldFromGrid({1.0 * i, 1.0 * j, 1.0 * k});
        nodes(i, j, k) = static_cast<float>(std::max(
            {0.03 - x[0], x[0] - 0.07, 0.02 - x[1], x[1] - 0.08, 0.025 - x[2], x[2] - 0.06}));
      }
  EXPECT_GT(expectSameBits(phi, nodes, g, 6.0 * kCell, 3.5 * kCell), 3000);
}

}  // namespace
}  // namespace fluidsound::sim
