// tests/sim/fluid/mesh_distance_test.cpp — nodal signed distances of placed meshes (OpenVDB
// meshToVolume) against closed-form distances of a box and a sphere, the clamp beyond the narrow
// band, independence of the triangles' orientation, and what a wall thinner than a cell gives.
#include "sim/fluid/mesh_distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "io/mesh_closedness.h"
#include "sim/fluid/solid_geometry.h"
#include "support/reference_distances.h"
#include "support/test_meshes.h"

namespace fluidsound::sim {
namespace {

/// OpenVDB returns the closest-triangle distance as a float in world units. For the grids below
/// (≤ 51 nodes per axis, h ≤ 1 cm, so |x| ≤ 0.5 m) float rounding of the positions and the
/// result is ≈ 2⁻²⁴·0.5 m ≈ 3e-8 m, and the index-space arithmetic inside OpenVDB adds a few
/// ulps of index coordinates (≈ 51·2⁻²⁴ cells ≈ 3e-6 h). 1e-5·h bounds both with margin; it is
/// far below anything the face weights can see.
constexpr double kFloatToleranceCells = 1e-5;

/// A 0.5 m cube of 50 cells of 1 cm, origin at 0.
sim::GridGeometry testGrid() { return sim::GridGeometry{{50, 50, 50}, 0.01, {0.0, 0.0, 0.0}}; }

double boxDistance(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return test::referenceBoxDistance(p, lo, hi);
}

/// Where the nodal values are exact [cells]: OpenVDB computes the distance to a triangle at
/// every voxel one step (of 26) from a voxel that the triangle passes within √3/2 of. For a
/// node at distance d from its closest point q, some node among its 26 neighbours lies within
/// √3/2 of q whenever d ≤ √11/2 ≈ 1.658 (the worst direction is towards (1, 1, 3), where the
/// point ½(1, 1, 3) is √3/2 from four neighbours; searched numerically over all directions);
/// near a flat part of the surface the zone reaches 1 + √3/2 ≈ 1.866.
const double kExactCells = std::sqrt(11.0) / 2.0;

/// Computed d against the reference distance r of every node, in the three zones of
/// meshNodeDistance's contract.
struct Comparison {
  double nearError = 0.0;  ///< max |d − r| where |r| ≤ kExactCells·h [m]
  double farShortfall =
      0.0;             ///< max of min(|r|, band) − |d| elsewhere (must be ≤ 0 + rounding) [m]
  int wrongSigns = 0;  ///< nodes with |r| > `signMargin` whose d has the other sign
  sim::Index3 worstNear{};
};

template <typename Reference>
Comparison compare(const sim::Array3f& d, const sim::GridGeometry& grid, double band,
                   double signMargin, const Reference& reference) {
  Comparison c;
  const double h = grid.cellSize;
  const sim::Index3 n = grid.nodeCount();
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const double r = reference(grid.worldFromGrid({double(i), double(j), double(k)}));
        const double v = d(i, j, k);
        if (std::abs(r) > signMargin && (v < 0.0) != (r < 0.0)) ++c.wrongSigns;
        if (std::abs(r) <= kExactCells * h) {
          if (std::abs(v - r) > c.nearError) {
            c.nearError = std::abs(v - r);
            c.worstNear = {i, j, k};
          }
        } else {
          const double expected = std::min(std::abs(r), band);
          c.farShortfall = std::max(c.farShortfall, expected - std::abs(v));
        }
      }
  return c;
}

/// The contract of meshNodeDistance against a reference that the mesh itself is within
/// `nearTolerance` of: exact near the surface, never below the true |d| (nor above the band)
/// farther out, the sign right wherever the reference is clear of the surface.
void expectContract(const Comparison& c, double nearTolerance) {
  EXPECT_LE(c.nearError, nearTolerance)
      << "worst node " << c.worstNear[0] << "," << c.worstNear[1] << "," << c.worstNear[2];
  EXPECT_LE(c.farShortfall, nearTolerance);
  EXPECT_EQ(c.wrongSigns, 0);
}

TEST(MeshDistance, ScaledTranslatedCubeIsExactNearItsFacesAndClampedBeyondTheBand) {
  // Claim: the cube [1, 2]³ of the file, scaled by 0.1 about the origin and translated by
  // t = (0.1337, 0.2113, 0.1771) m, is the box [0.1 + t, 0.2 + t]: nodes within √11/2 h of
  // it hold its exact signed distance, nodes farther out never less than min(|d|, 3h), nodes
  // beyond the band exactly ±3h, and every sign is right. Reference: closed form (boxDistance).
  // Tolerance: float rounding (kFloatToleranceCells); the mesh is the box itself (no faceting).
  const sim::GridGeometry grid = testGrid();
  const MeshPlacement placement{0.1, {0.1337, 0.2113, 0.1771}};
  const sim::Array3f d = meshNodeDistance(test::boxMesh({1, 1, 1}, {2, 2, 2}), placement, grid);
  ASSERT_EQ(d.size(), grid.nodeCount());
  const double h = grid.cellSize, band = 3 * h;
  const Vec3 lo{0.1 + 0.1337, 0.1 + 0.2113, 0.1 + 0.1771},
      hi{0.2 + 0.1337, 0.2 + 0.2113, 0.2 + 0.1771};
  const Comparison c = compare(d, grid, band, kFloatToleranceCells * h,
                               [&](const Vec3& p) { return boxDistance(p, lo, hi); });
  expectContract(c, kFloatToleranceCells * h);
  // The node nearest the box's centre is 4.3 cells from every face, the grid's corner far
  // outside: both exactly at the band's edge.
  EXPECT_EQ(d(28, 36, 32), static_cast<float>(-band));
  EXPECT_EQ(d(0, 0, 0), static_cast<float>(band));
  EXPECT_LE(*std::max_element(d.values().begin(), d.values().end()), static_cast<float>(band));
  EXPECT_GE(*std::min_element(d.values().begin(), d.values().end()), static_cast<float>(-band));
}

TEST(MeshDistance, SphereIsWithinTheFacetingOfItsMesh) {
  // Claim: for an icosphere (3 subdivisions, 1280 triangles) of radius r = 0.1 m = 10 h
  // translated to c, nodes within √11/2 h of the surface hold |p − c| − r up to the
  // faceting, and the contract holds farther out. Reference: the closed-form sphere distance.
  // The mesh lies between the balls of radius r·dMin and r (dMin: the least distance from the
  // centre to a face plane of the unit mesh), and signed distance decreases as a set grows, so
  // 0 ≤ d_mesh − d_sphere ≤ r (1 − dMin) =: s (0.045 h here, under the 0.1 h asked of a cut
  // cell). Tolerance: s plus float rounding.
  const sim::GridGeometry grid = testGrid();
  const sim::TriangleMesh sphere = test::icosphere(3);
  double dMin = 1.0;
  for (const auto& t : sphere.triangles) {
    const auto& a = sphere.vertices[t[0]];
    const auto& b = sphere.vertices[t[1]];
    const auto& e = sphere.vertices[t[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {e[0] - a[0], e[1] - a[1], e[2] - a[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                         u[0] * w[1] - u[1] * w[0]};
    dMin = std::min(dMin, (n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) /
                              std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
  }
  const double r = 0.1, h = grid.cellSize, band = 3 * h;
  const double sagitta = r * (1.0 - dMin);
  ASSERT_LT(sagitta, 0.1 * h);
  const Vec3 centre{0.2513, 0.2487, 0.2461};
  const sim::Array3f d = meshNodeDistance(sphere, {r, centre}, grid);
  const Comparison c = compare(d, grid, band, sagitta, [&](const Vec3& p) {
    return std::sqrt((p[0] - centre[0]) * (p[0] - centre[0]) +
                     (p[1] - centre[1]) * (p[1] - centre[1]) +
                     (p[2] - centre[2]) * (p[2] - centre[2])) -
           r;
  });
  expectContract(c, sagitta + kFloatToleranceCells * h);
}

TEST(MeshDistance, OrientationOfTheTrianglesDoesNotMatter) {
  // Claim: a box with every triangle flipped (normals inward) meets the same contract against
  // the same closed form: OpenVDB's sign comes from a flood fill, not from normals. (Beyond the
  // exact zone the two differ, by up to 0.83 h measured: the band expansion breaks ties
  // between triangles by the order of their corners.) Tolerance: float rounding.
  const sim::GridGeometry grid = testGrid();
  const double h = grid.cellSize;
  const Vec3 lo{double(0.11f), double(0.12f), double(0.13f)},
      hi{double(0.31f), double(0.22f), double(0.43f)};
  sim::TriangleMesh box = test::boxMesh({0.11f, 0.12f, 0.13f}, {0.31f, 0.22f, 0.43f});
  for (auto& t : box.triangles) std::swap(t[1], t[2]);
  ASSERT_LT(io::meshClosedness(box).signedVolume, 0.0);  // oriented inward
  const Comparison c =
      compare(meshNodeDistance(box, {}, grid), grid, 3 * h, kFloatToleranceCells * h,
              [&](const Vec3& p) { return boxDistance(p, lo, hi); });
  expectContract(c, kFloatToleranceCells * h);
}

TEST(MeshDistance, OpenBoxLosesItsInside) {
  // Claim (why io::requireClosedMesh rejects open solids): OpenVDB's sign is a flood fill from
  // outside, so through a hole as small as one missing triangle the outside floods the whole
  // inside of a 10 cm box: no node is negative, though the closed box has 10³ of them.
  const sim::GridGeometry grid{{20, 20, 20}, 0.01, {0.0, 0.0, 0.0}};
  sim::TriangleMesh box = test::boxMesh({0.0512f, 0.0512f, 0.0512f}, {0.1512f, 0.1512f, 0.1512f});
  const auto negativeNodes = [](const sim::Array3f& d) {
    return std::count_if(d.values().begin(), d.values().end(), [](float v) { return v < 0.0f; });
  };
  EXPECT_EQ(negativeNodes(meshNodeDistance(box, {}, grid)), 1000);
  box.triangles.pop_back();
  EXPECT_EQ(negativeNodes(meshNodeDistance(box, {}, grid)), 0);
}

TEST(MeshDistance, MeshOutsideTheGridLeavesEveryNodeAtTheBand) {
  // Claim: nodes farther than the band from the mesh (here all of them) hold +halfWidth·h;
  // a mesh without triangles gives the same. Reference: the documented clamp.
  const sim::GridGeometry grid{{8, 8, 8}, 0.01, {0.0, 0.0, 0.0}};
  const MeshDistanceSettings settings{2};
  const float band = static_cast<float>(2 * grid.cellSize);
  const sim::Array3f far = meshNodeDistance(
      test::boxMesh({0.5f, 0.5f, 0.5f}, {0.52f, 0.52f, 0.52f}), {}, grid, settings);
  EXPECT_EQ(*std::min_element(far.values().begin(), far.values().end()), band);
  EXPECT_EQ(*std::max_element(far.values().begin(), far.values().end()), band);
  const sim::Array3f none = meshNodeDistance(sim::TriangleMesh{}, {}, grid, settings);
  EXPECT_EQ(none.values(), far.values());
}

TEST(MeshDistance, InvalidSettingsAreRejected) {
  const sim::GridGeometry grid{{4, 4, 4}, 0.01, {0.0, 0.0, 0.0}};
  const sim::TriangleMesh box = test::boxMesh({0, 0, 0}, {0.02f, 0.02f, 0.02f});
  EXPECT_THROW(meshNodeDistance(box, {0.0, {}}, grid), std::invalid_argument);
  EXPECT_THROW(meshNodeDistance(box, {std::nan(""), {}}, grid), std::invalid_argument);
  EXPECT_THROW(meshNodeDistance(box, {}, grid, {1}), std::invalid_argument);
}

TEST(MeshDistance, ThinWallIsSeenOnlyWhenItHoldsANodePlane) {
  // Claim (a documented limit): a closed slab 2 mm thick in 5 mm cells, lying across the
  // x-plane of nodes i = 10 (x = 50 mm) with its lower face at x0 = 50 mm + a, gets its exact
  // signed distance at the nodes near it, so it is negative at i = 10 exactly when −2 mm < a < 0
  // (the slab holds the node plane) and the 64 u-faces of the wall's interior there close;
  // otherwise every node is outside (the nearest at min(|a|, |a + 2 mm|)) and no u-face of a
  // row through the wall closes: the wall leaks. Reference: the closed-form slab distance
  // (boxDistance) and sim::faceOpenFractions. Tolerance: float rounding (kFloatToleranceCells).
  const double h = 0.005, thickness = 0.002, plane = 0.05;
  const sim::GridGeometry grid{{20, 20, 20}, h, {0.0, 0.0, 0.0}};
  for (const double a :
       {-2.5e-3, -1.9e-3, -1.5e-3, -1.0e-3, -0.5e-3, -0.1e-3, 0.5e-3, 1.5e-3, 2.5e-3}) {
    SCOPED_TRACE("offset a = " + std::to_string(a * 1e3) + " mm");
    const std::array<float, 3> lo{float(plane + a), 0.02f, 0.02f};
    const std::array<float, 3> hi{float(plane + a + thickness), 0.08f, 0.08f};
    const sim::Array3f d = meshNodeDistance(test::boxMesh(lo, hi), {}, grid);
    // The reference is the slab the mesh really is (float corners).
    const Comparison c = compare(d, grid, 3 * h, kFloatToleranceCells * h, [&](const Vec3& p) {
      return boxDistance(p, {lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]});
    });
    expectContract(c, kFloatToleranceCells * h);

    const bool holdsPlane = a < 0.0 && a + thickness > 0.0;
    const auto open = sim::faceOpenFractions(d, grid);
    int closedFaces = 0;  // u-faces of the wall's interior (y, z in 30 … 70 mm), any i
    for (int k = 6; k < 14; ++k)
      for (int j = 6; j < 14; ++j)
        for (int i = 0; i <= 20; ++i) closedFaces += open[0](i, j, k) == 0.0f;
    EXPECT_EQ(closedFaces, holdsPlane ? 64 : 0);
    const double nearest =
        holdsPlane ? -std::min(-a, a + thickness) : std::min(std::abs(a), std::abs(a + thickness));
    EXPECT_NEAR(d(10, 10, 10), nearest, kFloatToleranceCells * h);
  }
}

}  // namespace
}  // namespace fluidsound::sim
