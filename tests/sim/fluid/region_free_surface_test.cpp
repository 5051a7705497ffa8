// Tests of sim/fluid/region_free_surface.h: a mesh liquid region's signed distance at the cell
// centres to its free faces — those not lying against a solid or a closed domain wall.
#include "sim/fluid/region_free_surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/fluid/solid_geometry.h"
#include "sim/scene.h"
#include "support/test_meshes.h"

namespace fluidsound::sim {
namespace {

constexpr double kCell = 0.01;     // h [m]
constexpr double kLevel = 0.0735;  // the water's top [m], inside a row of cells

/// A closed 16³ box of 1 cm cells.
sim::Domain tankDomain() {
  sim::Domain d;
  d.max = {0.16, 0.16, 0.16};
  d.cell = kCell;
  return d;
}

sim::GridGeometry gridOf(const sim::Domain& domain) {
  sim::Scene scene;
  scene.domain = domain;
  return scene.grid();
}

/// Exact signed distance from p to the axis-aligned box [lo, hi], negative inside.
double boxDistance(const Vec3& lo, const Vec3& hi, const Vec3& p) {
  double outside = 0.0, inside = -1e300;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max(lo[a] - p[a], p[a] - hi[a]);
    outside += d > 0.0 ? d * d : 0.0;
    inside = std::max(inside, d);
  }
  return outside > 0.0 ? std::sqrt(outside) : inside;
}

// Claim: water modelled as a mesh up to a wall off the cell planes (a box solid x < 31.7 mm),
// into a wall it overlaps (z > 123.3 mm) and onto the domain's floor and +x wall has only its
// top as surface: at every centre outside the walls within 1.5 cells of the top the distance is
// y − H, the cells the wall cuts included (the whole mesh's distance reads them 0.33 cell deep).
// Reference: y − H. Tolerance: 1e-5 h, float rounding of OpenVDB's exact closest-triangle
// distance (sim/fluid/mesh_distance.h's exact zone reaches 1.66 h).
TEST(RegionFreeSurface, FacesAgainstSolidsAndWallsAreNoSurface) {
  const double wallX = 0.0317, wallZ = 0.1233;
  const sim::Domain domain = tankDomain();
  const sim::GridGeometry grid = gridOf(domain);
  sim::Solid left, back;
  left.shape = sim::Box{{-0.01, -0.01, -0.01}, {wallX, 0.17, 0.17}};
  back.shape = sim::Box{{-0.01, -0.01, wallZ}, {0.17, 0.17, 0.17}};
  const std::vector<sim::Solid> solids{left, back};
  const sim::Array3f solidNodes = sim::solidNodeDistance(grid, domain, solids, 0.0);
  const sim::TriangleMesh water = test::boxMesh({static_cast<float>(wallX), 0.0f, 0.0f},
                                                {0.16f, static_cast<float>(kLevel), 0.14f});
  const sim::Array3f phi = regionFreeSurfaceAtCentres(water, solidNodes, grid);
  ASSERT_EQ(phi.size(), grid.cells);
  int checked = 0;
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const Vec3 x = grid.cellCentre(i, j, k);
        if (x[0] < wallX || x[2] > wallZ || std::abs(x[1] - kLevel) > 1.5 * kCell) continue;
        EXPECT_NEAR(phi(i, j, k), x[1] - kLevel, 1e-5 * kCell) << i << " " << j << " " << k;
        ++checked;
      }
  EXPECT_EQ(checked, 13 * 12 * 3);  // columns i = 3 … 15, k = 0 … 11; rows j = 6, 7, 8
  // Deeper than the band and with no free face near: the band's depth, −3h.
  EXPECT_FLOAT_EQ(phi(10, 1, 5), static_cast<float>(-3 * kCell));
}

// Claim: faces on the grid's boundary are no surface when the domain face is open as well (the
// liquid runs on through it): water filling a fully open box up to y = H reads y − H in every
// column within 1.5 cells of its top, the columns at the open sides included.
// Reference: y − H. Tolerance: 1e-5 h (float rounding of the exact distance).
TEST(RegionFreeSurface, FacesOnOpenDomainFacesAreNoSurface) {
  sim::Domain domain = tankDomain();
  domain.open.fill(true);
  const sim::GridGeometry grid = gridOf(domain);
  const sim::Array3f solidNodes = sim::solidNodeDistance(grid, domain, {}, 0.0);
  const sim::TriangleMesh water =
      test::boxMesh({0.0f, 0.0f, 0.0f}, {0.16f, static_cast<float>(kLevel), 0.16f});
  const sim::Array3f phi = regionFreeSurfaceAtCentres(water, solidNodes, grid);
  for (int k = 0; k < 16; ++k)
    for (int j = 6; j <= 8; ++j)
      for (int i = 0; i < 16; ++i)
        EXPECT_NEAR(phi(i, j, k), grid.cellCentre(i, j, k)[1] - kLevel, 1e-5 * kCell)
            << i << " " << j << " " << k;
}

// Claim: a region clear of every solid and wall is all free surface: the distance at the
// centres is the box's own, exact near its surface — its convex edges included, where values
// interpolated from the nodes read up to half a cell shallow.
// Reference: the exact distance to the box. Tolerance: 1e-5 h (float rounding) within 1.5 h.
TEST(RegionFreeSurface, ARegionClearOfSolidsIsAllSurface) {
  sim::Domain domain = tankDomain();
  domain.open.fill(true);
  const sim::GridGeometry grid = gridOf(domain);
  const sim::Array3f solidNodes = sim::solidNodeDistance(grid, domain, {}, 0.0);
  const Vec3 lo{0.04, 0.03, 0.05}, hi{0.12, 0.1, 0.11};
  const sim::TriangleMesh water = test::boxMesh({0.04f, 0.03f, 0.05f}, {0.12f, 0.1f, 0.11f});
  const sim::Array3f phi = regionFreeSurfaceAtCentres(water, solidNodes, grid);
  int checked = 0;
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const double exact = boxDistance(lo, hi, grid.cellCentre(i, j, k));
        if (std::abs(exact) > 1.5 * kCell) continue;
        EXPECT_NEAR(phi(i, j, k), exact, 1e-5 * kCell) << i << " " << j << " " << k;
        ++checked;
      }
  EXPECT_GT(checked, 500);
}

}  // namespace
}  // namespace fluidsound::sim
