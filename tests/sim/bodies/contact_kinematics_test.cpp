// tests/sim/bodies/contact_kinematics_test.cpp — closing speed, sliding speed and rolling rate
// at a contact (solids.md §1.4 eqs. 2, 4, 5) for motions whose answers are known by hand.
#include "sim/bodies/contact_kinematics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fluidsound::sim {
namespace {

/// Every case below is a handful of products of short decimals: only rounding, a few ulps.
constexpr double kRounding = 1e-14;

TEST(ContactKinematics, FallingBodyClosesAtItsSpeed) {
  // Claim: A falling at 2 m/s onto a static B (normal +y from B into A) closes at +2 m/s,
  // neither slides nor rolls; rising, it gives −2 m/s. Reference: eq. 2 by hand.
  const BodyMotion floor{};
  BodyMotion ball{{0.0, 0.01, 0.0}, {0.0, -2.0, 0.0}, {0.0, 0.0, 0.0}};
  ContactKinematics k = contactKinematics(ball, floor, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
  EXPECT_NEAR(k.normalSpeed, 2.0, kRounding);
  EXPECT_NEAR(k.tangentialSpeed, 0.0, kRounding);
  EXPECT_NEAR(k.rollingRate, 0.0, kRounding);
  ball.velocity = {0.0, 2.0, 0.0};
  k = contactKinematics(ball, floor, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
  EXPECT_NEAR(k.normalSpeed, -2.0, kRounding);
}

TEST(ContactKinematics, RollingWithoutSlippingHasNoSlipAndRateVOverR) {
  // Claim: a ball of radius r = 0.02 m rolling at v = 0.5 m/s in +x on a floor (ω = −v/r about
  // z) has zero slip at the contact point and rolling rate v/r = 25 rad/s. Reference: the
  // rolling condition v + ω × (−r ŷ) = 0.
  const double r = 0.02, v = 0.5;
  const BodyMotion ball{{0.0, r, 0.0}, {v, 0.0, 0.0}, {0.0, 0.0, -v / r}};
  const ContactKinematics k = contactKinematics(ball, {}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
  EXPECT_NEAR(k.normalSpeed, 0.0, kRounding);
  EXPECT_NEAR(k.tangentialSpeed, 0.0, kRounding);
  EXPECT_NEAR(k.rollingRate, v / r, kRounding * v / r);
}

TEST(ContactKinematics, SpinAboutTheNormalIsNotRolling) {
  // Claim: a top spinning about the contact normal neither rolls (eq. 5 keeps the tangent
  // part only) nor slides at the contact point on its axis.
  const BodyMotion top{{0.0, 0.05, 0.0}, {0.0, 0.0, 0.0}, {0.0, 30.0, 0.0}};
  const ContactKinematics k = contactKinematics(top, {}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
  EXPECT_NEAR(k.rollingRate, 0.0, kRounding);
  EXPECT_NEAR(k.tangentialSpeed, 0.0, kRounding);
}

TEST(ContactKinematics, BothBodiesMovingGiveRelativeValues) {
  // Claim: only relative motion counts, and B's rotation moves B's material at the point.
  // Setup: normal n = +z; A at rest; B translating at (0.3, 0, −0.4) and turning at ω_B =
  // (0, 0, 2) rad/s about its centre (1, 0, 0); point (0, 0, 0). Reference by hand:
  // v_B(P) = (0.3, 0, −0.4) + (0, 0, 2) × (−1, 0, 0) = (0.3, −2, −0.4); closing speed
  // (v_B − v_A)·n = −0.4; slip ‖(−0.3, 2)‖ = √4.09; ω_A − ω_B = (0, 0, −2) is along n: no roll.
  const BodyMotion a{{0.0, 0.0, 1.0}, {}, {}};
  const BodyMotion b{{1.0, 0.0, 0.0}, {0.3, 0.0, -0.4}, {0.0, 0.0, 2.0}};
  const ContactKinematics k = contactKinematics(a, b, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0});
  EXPECT_NEAR(k.normalSpeed, -0.4, kRounding);
  EXPECT_NEAR(k.tangentialSpeed, std::sqrt(4.09), kRounding);
  EXPECT_NEAR(k.rollingRate, 0.0, kRounding);
}

}  // namespace
}  // namespace fluidsound::sim
