// tests/sim/bodies/bullet_shape_test.cpp — Bullet shapes of specs: masses and inertias against
// closed forms, boxes that keep their size, a mesh hull about its centre of mass on its
// principal axes whose faces stay in place, and refused specs.
#include "sim/bodies/bullet_shape.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "support/body_test_meshes.h"

namespace fluidsound::sim {
namespace {

/// Closed forms of short decimals: double rounding, a few ulps.
constexpr double kRounding = 1e-12;

TEST(BulletShape, SphereHasClosedFormMassAndInertia) {
  // Claim: a steel sphere r = 1 cm has m = ρ·4πr³/3 and I = 2mr²/5 about every axis, and
  // Bullet's body frame is its centre. Reference: the closed forms.
  RigidBodySpec spec{.name = "ball", .shape = SphereShape{0.01}, .density = 7850.0};
  const BulletShape s = makeBulletShape(spec);
  const double mass = 7850.0 * 4.0 / 3.0 * std::numbers::pi * 1e-6;
  EXPECT_NEAR(s.mass, mass, kRounding * mass);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(s.principalMoments[a], 0.4 * mass * 1e-4, kRounding * mass * 1e-4);
  EXPECT_EQ(s.shape->getShapeType(), SPHERE_SHAPE_PROXYTYPE);
  EXPECT_TRUE(s.referenceFromBody == btTransform::getIdentity());
}

TEST(BulletShape, BoxKeepsItsOuterSizeWithASmallMargin) {
  // Claim: a 10 × 4 × 6 cm box has m = ρ·8abc, I_x = m(b² + c²)/3 (…), and keeps its outer
  // half-extents with a margin min(1 mm, 0.1·2 cm) = 1 mm inside. Reference: closed forms and
  // bullet_shape.h's margin rule.
  RigidBodySpec spec{.name = "brick", .shape = BoxShape{{0.05, 0.02, 0.03}}, .density = 2000.0};
  const BulletShape s = makeBulletShape(spec);
  const double mass = 2000.0 * 8.0 * 0.05 * 0.02 * 0.03;
  EXPECT_NEAR(s.mass, mass, kRounding * mass);
  EXPECT_NEAR(s.principalMoments[0], mass * (0.02 * 0.02 + 0.03 * 0.03) / 3.0, kRounding * mass);
  EXPECT_NEAR(s.principalMoments[1], mass * (0.03 * 0.03 + 0.05 * 0.05) / 3.0, kRounding * mass);
  EXPECT_NEAR(s.principalMoments[2], mass * (0.05 * 0.05 + 0.02 * 0.02) / 3.0, kRounding * mass);
  const auto* box = static_cast<const btBoxShape*>(s.shape.get());
  EXPECT_NEAR(box->getMargin(), 1e-3, kRounding);
  const btVector3 outer = box->getHalfExtentsWithMargin();
  EXPECT_NEAR(outer.x(), 0.05, kRounding);
  EXPECT_NEAR(outer.y(), 0.02, kRounding);
  EXPECT_NEAR(outer.z(), 0.03, kRounding);
}

TEST(BulletShape, DynamicMeshHullSitsOnCentreOfMassAndPrincipalAxes) {
  // Claim: a box mesh [0.1, 0.3] × [0, 0.1] × [0, 0.05] m (origin at a corner, not the centre)
  // gets its body frame at the centre (0.2, 0.05, 0.025) on principal axes, the box's closed-
  // form mass and moments, and a hull whose support along each principal axis (margin
  // included) is the box's half-extent along it: shrinking by the margin moved faces, not the
  // body's size. Reference: closed forms. Tolerances: float vertices (2⁻²⁴·0.3 m ≈ 2e-8 m)
  // give 1e-7 m for the centre and 1e-6 relative for the moments; the support also carries
  // btConvexHullComputer's shrink, which it does in fixed-point coordinates: measured 1.6e-6 m
  // too large (0.16 % of the 1 mm shrink), so 5e-6 m (0.5 % of the margin) there.
  const TriangleMesh mesh = test::boxMesh({0.1, 0.0, 0.0}, {0.3, 0.1, 0.05});
  RigidBodySpec spec{.name = "block", .shape = mesh, .density = 1000.0};
  const BulletShape s = makeBulletShape(spec);
  const double mass = 1000.0 * 0.2 * 0.1 * 0.05;
  EXPECT_NEAR(s.mass, mass, 1e-6 * mass);
  const btVector3 centre = s.referenceFromBody.getOrigin();
  EXPECT_NEAR(centre.x(), 0.2, 1e-7);
  EXPECT_NEAR(centre.y(), 0.05, 1e-7);
  EXPECT_NEAR(centre.z(), 0.025, 1e-7);
  // Principal moments ascend: the smallest is about the longest (x) edge.
  const Vec3 half{0.1, 0.05, 0.025};
  const double expected[3] = {mass * (half[1] * half[1] + half[2] * half[2]) / 3.0,
                              mass * (half[2] * half[2] + half[0] * half[0]) / 3.0,
                              mass * (half[0] * half[0] + half[1] * half[1]) / 3.0};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.principalMoments[k], expected[k], 1e-6 * expected[k]);
  ASSERT_EQ(s.shape->getShapeType(), CONVEX_HULL_SHAPE_PROXYTYPE);
  const auto* hull = static_cast<const btConvexHullShape*>(s.shape.get());
  EXPECT_GT(hull->getMargin(), 0.0);
  EXPECT_LE(hull->getMargin(), kMaxCollisionMargin);
  const btMatrix3x3& rotation = s.referenceFromBody.getBasis();
  for (int k = 0; k < 3; ++k) {
    // Body axis k in the mesh frame is column k of the rotation; it must be a box axis.
    const btVector3 axis = rotation.getColumn(k);
    int boxAxis = 0;
    for (int a = 1; a < 3; ++a)
      if (std::abs(axis[a]) > std::abs(axis[boxAxis])) boxAxis = a;
    EXPECT_NEAR(std::abs(axis[boxAxis]), 1.0, 1e-9) << "body axis " << k;
    for (const double sign : {-1.0, 1.0}) {
      btVector3 direction(0, 0, 0);
      direction[k] = sign;
      const double support = hull->localGetSupportingVertex(direction).dot(direction);
      EXPECT_NEAR(support, half[boxAxis], 5e-6) << "body axis " << k << " sign " << sign;
    }
  }
}

TEST(BulletShape, StaticMeshIsItsTrianglesWithoutMass) {
  // Claim: a static mesh collides as its own triangles (btBvhTriangleMeshShape), massless, in
  // its own frame.
  RigidBodySpec spec{
      .name = "floor", .shape = test::boxMesh({-1, -0.1, -1}, {1, 0, 1}), .isStatic = true};
  const BulletShape s = makeBulletShape(spec);
  EXPECT_EQ(s.shape->getShapeType(), TRIANGLE_MESH_SHAPE_PROXYTYPE);
  EXPECT_EQ(s.mass, 0.0);
  EXPECT_TRUE(s.referenceFromBody == btTransform::getIdentity());
  btVector3 lo, hi;
  s.shape->getAabb(btTransform::getIdentity(), lo, hi);
  EXPECT_NEAR(hi.y(), 0.0, 1e-6);
}

TEST(BulletShape, RefusesBadSizesAndDensities) {
  // Claim: sizes and densities that make no body are refused, naming the body.
  EXPECT_THROW(makeBulletShape({.name = "a", .shape = SphereShape{0.0}}), std::invalid_argument);
  EXPECT_THROW(makeBulletShape({.name = "b", .shape = BoxShape{{0.1, -0.1, 0.1}}}),
               std::invalid_argument);
  EXPECT_THROW(makeBulletShape({.name = "c", .shape = SphereShape{0.1}, .density = 0.0}),
               std::invalid_argument);
  TriangleMesh square;
  square.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  try {
    makeBulletShape({.name = "sheet", .shape = square});
    FAIL() << "an open mesh was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sheet"), std::string::npos) << e.what();
  }
  // A static body needs no density.
  EXPECT_NO_THROW(
      makeBulletShape({.name = "d", .shape = SphereShape{0.1}, .density = 0.0, .isStatic = true}));
}

}  // namespace
}  // namespace fluidsound::sim
