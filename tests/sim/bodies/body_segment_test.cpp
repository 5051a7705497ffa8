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

}  // namespace
}  // namespace fluidsound::sim
