// tests/acoustics/modal/contact_impacts_test.cpp — impacts from a contact log: a rule-by-rule check
// on a hand-made log, and a steel ball dropped on a steel plate in the rigid-body stage (Bullet):
// each bounce one impact of impulse m(1 + e)v at the right time and place, and none from the
// resting contact that follows (the issue: "bodies at rest make none").
#include "acoustics/modal/contact_impacts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "acoustics/modal/hertz_contact.h"
#include "sim/bodies/rigid_world.h"
#include "support/body_contacts.h"
#include "support/steel_plate_model.h"

namespace fluidsound::acoustics {
namespace {

/// A free steel plate 0.2 × 0.01 × 0.2 m, centred on its body's origin: its lowest 20 modes.
const ModalModel& plateModel() {
  static const ModalModel model = test::steelPlateModel(0.2, 20);
  return model;
}

double noDuration(const BodyContactPoint&, double) { return 0.0; }

TEST(ContactImpacts, AFreshFastTouchIsAnImpactAndItsContinuationIsNot) {
  const ModalModel& model = plateModel();
  const Eigen::Vector3d top(0.0, 0.005, 0.0), down(0.0, -0.1, 0.0), load(0.0, -1e-3, 0.0);
  const std::vector<BodyContactPoint> log = {
      {0.010, 7, top, down, 2.0},          // a fresh touch at 2 m/s: an impact
      {0.010, 7, top + Eigen::Vector3d(0.02, 0, 0), down, 1.5},  // the same substep and pair: the same impact
      {0.011, 7, top, down, 0.5},          // still closing in the next substep: the same impact
      {0.012, 7, top, load, 0.0},          // resting
      {0.013, 7, top, load, 0.01},         // slower than 0.02 m/s: nothing
      {0.020, 7, top, down, 1.0},          // closing again after a pause: a new impact
      {0.020, 9, top, down, 1.0},          // another body at the same time: its own impact
  };
  const std::vector<ModalImpact> impacts = impactsFromContacts(log, model, {}, noDuration);
  ASSERT_EQ(impacts.size(), 3u);
  EXPECT_NEAR(impacts[0].time, 0.009, 1e-12);  // the substep's start
  EXPECT_NEAR(impacts[0].impulse.y(), -0.2, 1e-12);
  EXPECT_EQ(impacts[0].surfaceNode, nearestSurfaceNode(model, top + Eigen::Vector3d(0.01, 0, 0)));
  EXPECT_NEAR(impacts[1].time, 0.019, 1e-12);
  EXPECT_NEAR(impacts[2].time, 0.019, 1e-12);
}

// Bullet's drop: a steel ball (r = 1 cm) from 0.2 m onto a static steel plate, restitution 0.5. The
// first impact at √(2h/g) = 0.2019 s within a substep, its impulse m(1 + e)√(2gh) within 5 % (the
// rigid-body stage's own tolerance for the same drop), pointing down, at the node under the ball;
// each later bounce slower by about e; none once the ball rests (0.7–1.0 s), though the log holds a
// resting contact point in every substep there.
TEST(ContactImpacts, BouncingBallGivesOneImpactPerBounceAndNoneAtRest) {
  const SolidMaterial steel = *findSolidMaterial("steel");
  sim::RigidBodySpec plate{"plate", sim::BoxShape{{0.1, 0.005, 0.1}}, steel.density, true};
  plate.restitution = 1.0;
  const double radius = 0.01, height = 0.2, gravity = 9.81;
  sim::RigidBodySpec ball{"ball", sim::SphereShape{radius}, steel.density, false};
  ball.position = {0.03, 0.005 + radius + height, 0.02};
  ball.restitution = 0.5;
  sim::RigidWorld world({plate, ball});
  world.advance(1.0);

  const std::vector<BodyContactPoint> onPlate = test::contactsOn(world, 0);
  std::size_t restingPoints = 0;
  for (const sim::ContactRecord& c : world.contacts()) {
    ASSERT_EQ(c.bodyA, 0);  // the plate: the lower index
    if (c.time > 0.7) ++restingPoints;
  }
  const double mass = 4.0 / 3.0 * std::numbers::pi * std::pow(radius, 3) * steel.density;
  const auto hertz = [&](const BodyContactPoint&, double speed) {
    return hertzImpact(mass, radius, effectiveContactModulus(steel, steel), speed).duration;
  };
  const std::vector<ModalImpact> impacts = impactsFromContacts(onPlate, plateModel(), {}, hertz);
  ASSERT_GE(impacts.size(), 3u);
  const double speed = std::sqrt(2.0 * gravity * height);
  EXPECT_NEAR(impacts[0].time, std::sqrt(2.0 * height / gravity), 1e-3);
  EXPECT_NEAR(-impacts[0].impulse.y(), mass * 1.5 * speed, 0.05 * mass * 1.5 * speed);
  EXPECT_EQ(impacts[0].surfaceNode, nearestSurfaceNode(plateModel(), {0.03, 0.005, 0.02}));
  EXPECT_NEAR(impacts[0].contactDuration, 70.7e-6 * std::pow(speed, -0.2), 0.01 * 70.7e-6);
  for (std::size_t i = 1; i < impacts.size(); ++i)
    EXPECT_LT(-impacts[i].impulse.y(), 0.7 * -impacts[i - 1].impulse.y()) << i;  // e = 0.5, and inelastic below 0.2 m/s
  EXPECT_LT(impacts.back().time, 0.7);
  EXPECT_GT(restingPoints, 250u);
}

}  // namespace
}  // namespace fluidsound::acoustics
