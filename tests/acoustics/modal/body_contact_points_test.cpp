// Tests of acoustics/modal/body_contact_points.h: a body's side of the contact log in its own
// frame, where its modes are.
#include "acoustics/modal/body_contact_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace fluidsound::acoustics {
namespace {

// Claim: a record's world impulse and normal are turned into each body's frame by the inverse of
// that body's rotation in the substep, and B receives A's impulse reversed; the body's origin is
// where its local point, turned back, meets the contact. Reference: a body turned 90° about z
// (its x axis along the world's y): a world impulse along −y is −x in its frame. To rounding.
TEST(BodyContactPoints, TurnsTheImpulseIntoEachBodysFrame) {
  sim::ContactLog log;
  log.bodies = {{"ball", 0.1, false, 0.01}, {"table", 0.0, true, 0.02}};
  sim::ContactRecord c;
  c.time = 0.01;
  c.bodyA = 0;
  c.bodyB = 1;
  c.position = {1.0, 2.0, 3.0};
  c.normal = {0.0, 1.0, 0.0};  // from the table into the ball
  c.normalImpulse = 0.2;
  c.frictionImpulse = {0.05, 0.0, 0.0};
  c.normalSpeed = 1.0;
  c.rollingRate = 10.0;
  c.localPointA = {-0.01, 0.0, 0.0};  // the ball's −x side, turned to face down
  c.localPointB = {0.0, 0.02, 0.0};
  c.orientationA = sim::quaternionFromAxisAngle({0.0, 0.0, 1.0}, std::numbers::pi / 2);
  log.records = {c};

  const std::vector<BodyContactPoint> ball = bodyContactPoints(log, 0);
  ASSERT_EQ(ball.size(), 1u);
  // World impulse on the ball (0.05, 0.2, 0); in its frame (turned −90° about z): (0.2, −0.05, 0).
  EXPECT_NEAR(ball[0].impulse.x(), 0.2, 1e-15);
  EXPECT_NEAR(ball[0].impulse.y(), -0.05, 1e-15);
  EXPECT_NEAR(ball[0].normal.x(), 1.0, 1e-15);
  EXPECT_NEAR((ball[0].origin - Eigen::Vector3d(1.0, 2.01, 3.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(ball[0].rollingSpeed, 10.0 * 0.01, 1e-15) << "the ball rolls: its own radius";

  const std::vector<BodyContactPoint> table = bodyContactPoints(log, 1);
  ASSERT_EQ(table.size(), 1u);
  EXPECT_NEAR(table[0].impulse.x(), -0.05, 1e-15);
  EXPECT_NEAR(table[0].impulse.y(), -0.2, 1e-15);
  EXPECT_NEAR(table[0].normal.y(), -1.0, 1e-15);
  EXPECT_EQ(table[0].other, 0);
  EXPECT_NEAR(table[0].rollingSpeed, 10.0 * 0.01, 1e-15) << "the moving ball's radius, not the table's";
  EXPECT_THROW(bodyContactPoints(log, 2), std::invalid_argument);
}

}  // namespace
}  // namespace fluidsound::acoustics
