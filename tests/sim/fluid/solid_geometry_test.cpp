// tests/sim/fluid/solid_geometry_test.cpp — nodal solid distances against closed-form distances of
// boxes, rotated boxes, spheres and domain walls; face-area weights against exact areas of plane
// cuts (Batty, Bertails & Bridson 2007, §3); kinematic solid velocities against their paths.
#include "sim/fluid/solid_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "support/reference_distances.h"

namespace fluidsound::sim {
namespace {

/// Distances are computed in double and stored as float: the storage rounds a value ≤ 2 m by at
/// most 2·2⁻²⁴ ≈ 1.2e-7 m. 1e-6 m leaves room for the rotation's trigonometry and is still
/// 1e-4 of the smallest cell used here.
constexpr double kDistanceTolerance = 1e-6;
/// Face fractions are exact for plane cuts up to float storage of distances and result:
/// relative 1e-7 on the corner values → ≈ 1e-6 on a fraction.
constexpr double kFractionTolerance = 1e-5;

constexpr int kCells = 16;
constexpr double kCell = 1.0 / kCells;  // h [m]: a 1 m cube in 16 cells

GridGeometry unitGrid() { return GridGeometry{{kCells, kCells, kCells}, kCell, {0.0, 0.0, 0.0}}; }

/// A unit-cube domain with every face open: no walls, so only the solids contribute.
Domain openDomain() {
  Domain d;
  d.min = {0.0, 0.0, 0.0};
  d.max = {1.0, 1.0, 1.0};
  d.cell = kCell;
  d.open = {true, true, true, true, true, true};
  return d;
}

double axisBoxDistance(const Vec3& p, const Vec3& lo, const Vec3& hi) { return test::referenceBoxDistance(p, lo, hi); }

TEST(SolidGeometry, ScaledTranslatedBoxDistanceIsExact) {
  // Claim: a unit box scaled by 0.25 about the origin and translated by 0.3 m is the box
  // [0.3, 0.55]³, and the node values are its exact signed distance. Reference: closed form
  // (axisBoxDistance). Tolerance: float storage (kDistanceTolerance).
  Solid s;
  s.shape = Box{{0, 0, 0}, {1, 1, 1}};
  s.scale = 0.25;
  s.translate = {0.3, 0.3, 0.3};
  const GridGeometry grid = unitGrid();
  const Array3f d = solidNodeDistance(grid, openDomain(), std::span(&s, 1), 0.0);
  ASSERT_EQ(d.size(), grid.nodeCount());
  for (int k = 0; k <= kCells; ++k)
    for (int j = 0; j <= kCells; ++j)
      for (int i = 0; i <= kCells; ++i) {
        const Vec3 p = grid.worldFromGrid({double(i), double(j), double(k)});
        ASSERT_NEAR(d(i, j, k), axisBoxDistance(p, {0.3, 0.3, 0.3}, {0.55, 0.55, 0.55}),
                    kDistanceTolerance)
            << "node " << i << "," << j << "," << k;
      }
}

TEST(SolidGeometry, RotatedBoxIsASlopedFloor) {
  // Claim: a wide slab rotated 30° about z (about its centre c) is a floor whose top is the plane
  // n·(p − c) = half thickness, n = (−sin 30°, cos 30°, 0): near the middle of the slope, where
  // that plane is the nearest feature, the distance above and below it is n·(p − c) − ½t.
  // Reference: closed form of the plane distance. Tolerance: float storage.
  constexpr double kSlopeDegrees = 30.0;
  constexpr double kHalfThickness = 0.3;  // m
  Solid s;
  s.shape = Box{{-1.0, -kHalfThickness, -1.0}, {2.0, kHalfThickness, 2.0}};  // centre (0.5, 0, 0.5)
  s.rotateDegrees = {0.0, 0.0, kSlopeDegrees};
  const GridGeometry grid = unitGrid();
  const Array3f d = solidNodeDistance(grid, openDomain(), std::span(&s, 1), 0.0);
  const double angle = kSlopeDegrees * std::numbers::pi / 180.0;
  const Vec3 normal{-std::sin(angle), std::cos(angle), 0.0};
  int checked = 0;
  for (int k = 0; k <= kCells; ++k)
    for (int j = 0; j <= kCells; ++j)
      for (int i = 0; i <= kCells; ++i) {
        const Vec3 p = grid.worldFromGrid({double(i), double(j), double(k)});
        const double height = normal[0] * (p[0] - 0.5) + normal[1] * p[1] - kHalfThickness;
        // Only nodes within 0.25 m of the top plane and well inside its extent: the other
        // faces are ≥ 1 m away there.
        if (std::abs(height) > 0.25) continue;
        ++checked;
        ASSERT_NEAR(d(i, j, k), height, kDistanceTolerance) << "node " << i << "," << j << "," << k;
      }
  EXPECT_GT(checked, 100);
}

TEST(SolidGeometry, SphereDistanceIsExact) {
  // Claim: a sphere (centre (1, 2, 1) m, radius 1 m) scaled by 0.2 about the origin and moved by
  // translate + path is the sphere |p − c| = 0.2 with c = (0.2, 0.4, 0.2) + (0.3, 0, 0.3)
  // + (0, −0.1, 0) (path at t = 1 s, halfway between keys). Reference: |p − c| − r.
  // Tolerance: float storage.
  Solid s;
  s.shape = Sphere{{1.0, 2.0, 1.0}, 1.0};
  s.scale = 0.2;
  s.translate = {0.3, 0.0, 0.3};
  s.path = {PathKey{0.0, {0, 0, 0}}, PathKey{2.0, {0, -0.2, 0}}};
  const GridGeometry grid = unitGrid();
  const Array3f d = solidNodeDistance(grid, openDomain(), std::span(&s, 1), 1.0);
  const Vec3 c{0.5, 0.3, 0.5};
  for (int k = 0; k <= kCells; ++k)
    for (int j = 0; j <= kCells; ++j)
      for (int i = 0; i <= kCells; ++i) {
        const Vec3 p = grid.worldFromGrid({double(i), double(j), double(k)});
        const double r = std::hypot(p[0] - c[0], p[1] - c[1], p[2] - c[2]);
        ASSERT_NEAR(d(i, j, k), r - 0.2, kDistanceTolerance)
            << "node " << i << "," << j << "," << k;
      }
}

TEST(SolidGeometry, ClosedDomainWallsAreSolidBehindTheBoundaryAndOpenTopIsNot) {
  // Claim: with every face closed but +y, the distance is min(x − 0, 1 − x, y − 0, z − 0, 1 − z)
  // (no +y wall), negative outside the domain box. The grid reaches 2 cells beyond the domain
  // on every side to see the negative values. Reference: plane distances. Tolerance: float.
  Domain domain = openDomain();
  domain.open = {false, false, false, true, false, false};
  constexpr int kMargin = 2;
  const GridGeometry grid{{kCells + 2 * kMargin, kCells + 2 * kMargin, kCells + 2 * kMargin},
                          kCell,
                          {-kMargin * kCell, -kMargin * kCell, -kMargin * kCell}};
  const Array3f d = solidNodeDistance(grid, domain, {}, 0.0);
  for (int k = 0; k <= grid.cells[2]; ++k)
    for (int j = 0; j <= grid.cells[1]; ++j)
      for (int i = 0; i <= grid.cells[0]; ++i) {
        const Vec3 p = grid.worldFromGrid({double(i), double(j), double(k)});
        const double expected = std::min({p[0], 1.0 - p[0], p[1], p[2], 1.0 - p[2]});
        ASSERT_NEAR(d(i, j, k), expected, kDistanceTolerance)
            << "node " << i << "," << j << "," << k;
      }
}

TEST(SolidGeometry, MeshSolidsAreRejected) {
  Solid s;
  s.shape = MeshFile{"glass.obj"};
  EXPECT_THROW(solidNodeDistance(unitGrid(), openDomain(), std::span(&s, 1), 0.0),
               std::invalid_argument);
  EXPECT_THROW(solidFaceVelocity(unitGrid(), openDomain(), std::span(&s, 1), 0.0),
               std::invalid_argument);
}

TEST(SolidGeometry, HalfCoveredFaceIsHalfOpen) {
  // Claim: a face cut through its middle by a plane is half solid, whichever way the plane runs
  // (parallel to an edge, or along a diagonal). Reference: area 1/2 by symmetry.
  EXPECT_NEAR(solidFractionOfSquare(-1.0, -1.0, 1.0, 1.0), 0.5, kFractionTolerance);
  EXPECT_NEAR(solidFractionOfSquare(-1.0, 1.0, 1.0, -1.0), 0.5, kFractionTolerance);
  EXPECT_NEAR(solidFractionOfSquare(-1.0, 0.0, 1.0, 0.0), 0.5, kFractionTolerance);
  // A corner cut by φ = x + y − 0.5 on the unit square: the triangle x + y ≤ 0.5, area 1/8.
  EXPECT_NEAR(solidFractionOfSquare(-0.5, 0.5, 1.5, 0.5), 0.125, kFractionTolerance);
  // Its complement: φ = 1.5 − x − y, inside where x + y ≥ 1.5, area 1/8.
  EXPECT_NEAR(solidFractionOfSquare(1.5, 0.5, -0.5, 0.5), 0.125, kFractionTolerance);
}

TEST(SolidGeometry, FaceWeightsOfASlopedFloorAreExactAreas) {
  // Claim: for a planar floor y < y0 + x·tan α (a slab rotated 20° about z), the open fraction
  // of each x-face (a square in the (y, z) plane at fixed x) is its part above the floor height
  // there; of each y-face, the part of its x-extent where the floor is still below it.
  // Reference: exact areas of plane cuts (solidFractionOfSquare is exact for a plane).
  // Tolerance: kFractionTolerance.
  constexpr double kSlopeDegrees = 20.0;
  const double slope = std::tan(kSlopeDegrees * std::numbers::pi / 180.0);
  const double y0 = 0.31;  // m, floor height at x = 0 (not on a grid plane)
  Solid s;
  const double c = std::cos(kSlopeDegrees * std::numbers::pi / 180.0);
  // A slab of half thickness 1 m whose top plane passes through (0, y0): centre below it.
  s.shape = Box{{-3.0, -1.0, -3.0}, {3.0, 1.0, 3.0}};
  s.rotateDegrees = {0.0, 0.0, kSlopeDegrees};
  s.translate = {std::sin(kSlopeDegrees * std::numbers::pi / 180.0), y0 - c, 0.0};
  const GridGeometry grid = unitGrid();
  const auto open =
      faceOpenFractions(solidNodeDistance(grid, openDomain(), std::span(&s, 1), 0.0), grid);
  const auto floorAt = [&](double x) { return y0 + x * slope; };
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      // x-face at x = i·h spans y ∈ [j h, (j+1) h]: open part above the floor.
      const double expected = std::clamp(((j + 1) * kCell - floorAt(i * kCell)) / kCell, 0.0, 1.0);
      ASSERT_NEAR(open[0](i, j, 3), expected, kFractionTolerance) << "u face " << i << "," << j;
    }
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      // y-face at y = j·h spans x ∈ [i h, (i+1) h]: open where the rising floor is still below
      // y, i.e. x < (y − y0)/tan α.
      const double xCross = (j * kCell - y0) / slope;
      const double expected = std::clamp((xCross - i * kCell) / kCell, 0.0, 1.0);
      ASSERT_NEAR(open[1](i, j, 3), expected, kFractionTolerance) << "v face " << i << "," << j;
    }
}

TEST(SolidGeometry, FlatWallOnAGridPlaneClosesItsFacesAndOpensTheNext) {
  // Claim: a wall that coincides with grid planes gives weights 0 or 1 only: the closed domain
  // walls close every boundary face (they lie in the walls), the open top leaves its boundary
  // faces open, and a box floor with its top exactly on the plane y = 4h closes the y-faces in
  // that plane and below, the x-faces below it, and leaves all faces above it fully open.
  // Reference: the geometry. Tolerance: exact (0 and 1 are exact in float).
  Domain domain = openDomain();
  domain.open = {false, false, false, true, false, false};
  Solid floor;
  floor.shape = Box{{-1.0, -1.0, -1.0}, {2.0, 4 * kCell, 2.0}};
  const GridGeometry grid = unitGrid();
  const auto open =
      faceOpenFractions(solidNodeDistance(grid, domain, std::span(&floor, 1), 0.0), grid);
  for (int a = 0; a < 3; ++a) {
    const Index3 n = grid.faceCount(a);
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          const Index3 f{i, j, k};
          const bool onClosedWall =
              (a != 1 && (f[a] == 0 || f[a] == n[a] - 1)) || (a == 1 && f[1] == 0);
          const bool belowFloor = a == 1 ? j <= 4 : j < 4;
          const float expected = onClosedWall || belowFloor ? 0.0f : 1.0f;
          ASSERT_EQ(open[a](i, j, k), expected)
              << "axis " << a << " face " << i << "," << j << "," << k;
        }
  }
}

TEST(SolidGeometry, PathIsLinearBetweenKeysAndHeldOutside) {
  // Claim: translation interpolates linearly between keys and holds the end keys; the velocity
  // is the slope of the current segment and zero outside the keyed interval (DESIGN.md solids).
  const std::vector<PathKey> path{{0.5, {0, 0, 0}}, {1.0, {0, -0.15, 0}}, {2.0, {0.1, -0.15, 0}}};
  EXPECT_EQ(pathTranslation(path, 0.0), (Vec3{0, 0, 0}));
  EXPECT_NEAR(pathTranslation(path, 0.75)[1], -0.075, 1e-15);
  EXPECT_NEAR(pathTranslation(path, 1.5)[0], 0.05, 1e-15);
  EXPECT_EQ(pathTranslation(path, 3.0), (Vec3{0.1, -0.15, 0}));
  EXPECT_EQ(pathVelocity(path, 0.25), (Vec3{0, 0, 0}));
  EXPECT_NEAR(pathVelocity(path, 0.5)[1], -0.3, 1e-15);
  EXPECT_NEAR(pathVelocity(path, 1.0)[0], 0.1, 1e-15);
  EXPECT_EQ(pathVelocity(path, 2.0), (Vec3{0, 0, 0}));
  EXPECT_EQ(pathVelocity({}, 1.0), (Vec3{0, 0, 0}));
}

TEST(SolidGeometry, FaceVelocityIsTheNearestSolidsPathVelocity) {
  // Claim: faces nearer to a sphere moving at (0, −0.3, 0) m/s than to any wall carry its
  // velocity component (v = −0.3, u = w = 0); faces nearer to a wall carry 0; static solids give
  // zero everywhere. Reference: the path slope. Tolerance: float rounding of −0.3 (exact check
  // against the float value).
  Domain domain = openDomain();
  domain.open = {false, false, false, false, false, false};
  Solid sphere;
  sphere.shape = Sphere{{0.5, 0.5, 0.5}, 0.2};
  sphere.path = {PathKey{0.0, {0, 0, 0}}, PathKey{1.0, {0, -0.3, 0}}};
  const GridGeometry grid = unitGrid();
  const auto v = solidFaceVelocity(grid, domain, std::span(&sphere, 1), 0.5);
  EXPECT_EQ(v[1](8, 5, 8), -0.3f);  // (0.53, 0.31, 0.53) m: inside the sphere (centre y 0.35 m)
  EXPECT_EQ(v[1](8, 0, 8), 0.0f);   // on the floor
  EXPECT_EQ(v[0](8, 5, 8), 0.0f);   // u of a moving-sphere face: no x motion
  sphere.path.clear();
  const auto still = solidFaceVelocity(grid, domain, std::span(&sphere, 1), 0.5);
  for (int a = 0; a < 3; ++a)
    EXPECT_EQ(*std::max_element(still[a].values().begin(), still[a].values().end()), 0.0f);
}

}  // namespace
}  // namespace fluidsound::sim
