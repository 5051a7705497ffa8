// Tests of sim/bodies/body_segment.h: the line of sight through a body where its spec places it.
#include "sim/bodies/body_segment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/body_test_meshes.h"

namespace fluidsound::sim {
namespace {

// A box 0.2 × 0.02 × 0.2 m turned 90° about z (its thin side now along x) at (1, 0, 0): a segment
// along x through it crosses; one along y at x = 1.05 (outside its 1 cm half thickness, now in x)
// misses; one ending short of it misses. A sphere and an icosphere mesh of radius 0.1 at the
// origin: a segment through the centre crosses both, one passing 0.15 m away misses both.
// Reference: the geometry.
TEST(BodySegment, CrossesWhatItPassesThroughWhereTheSpecPlacesIt) {
  RigidBodySpec board{"board", BoxShape{{0.1, 0.01, 0.1}}, 750.0, true, {1.0, 0.0, 0.0}};
  board.rotation = quaternionFromAxisAngle({0, 0, 1}, std::numbers::pi / 2);
  EXPECT_TRUE(segmentCrossesBody(board, {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}));
  EXPECT_FALSE(segmentCrossesBody(board, {1.05, -1.0, 0.0}, {1.05, 1.0, 0.0}));
  EXPECT_TRUE(segmentCrossesBody(board, {1.005, -1.0, 0.0}, {1.005, 1.0, 0.0}));
  EXPECT_FALSE(segmentCrossesBody(board, {0.0, 0.0, 0.0}, {0.98, 0.0, 0.0}));
  EXPECT_NEAR(boundingRadius(board), std::sqrt(0.02 + 1e-4), 1e-12);
  const RigidBodySpec ball{"ball", SphereShape{0.1}, 7850.0, true};
  const RigidBodySpec mesh{"mesh", test::icosphereMesh(0.1, 2), 7850.0, true};
  for (const RigidBodySpec& body : {ball, mesh}) {
    EXPECT_TRUE(segmentCrossesBody(body, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0})) << body.name;
    EXPECT_FALSE(segmentCrossesBody(body, {-1.0, 0.15, 0.0}, {1.0, 0.15, 0.0})) << body.name;
  }
}

// Claim: a point is inside a body where its shape is: the icosphere mesh of radius 0.1 (its
// vertices on the sphere, its faces within 2 % of it at level 2) holds a point 0.09 m out and not
// one 0.11 m out, in every axis direction; a box its interior only. Reference: the geometry.
TEST(BodySegment, ContainsThePointsInsideItsShape) {
  const RigidBodySpec mesh{"mesh", test::icosphereMesh(0.1, 2), 7850.0, true};
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {-1.0, 1.0}) {
      Vec3 in{0.001, 0.0013, 0.0007}, out = in;
      in[axis] += side * 0.09;
      out[axis] += side * 0.11;
      EXPECT_TRUE(bodyContainsPoint(mesh, in)) << axis << " " << side;
      EXPECT_FALSE(bodyContainsPoint(mesh, out)) << axis << " " << side;
    }
  const RigidBodySpec box{"box", BoxShape{{0.1, 0.01, 0.2}}, 750.0, true};
  EXPECT_TRUE(bodyContainsPoint(box, {0.09, -0.009, 0.19}));
  EXPECT_FALSE(bodyContainsPoint(box, {0.09, 0.011, 0.0}));
  EXPECT_EQ(boundingHalfExtents(box), (Vec3{0.1, 0.01, 0.2}));
}

}  // namespace
}  // namespace fluidsound::sim
