// tests/sim/bodies/quaternion_test.cpp — unit-quaternion orientations: axis–angle rotations
// by hand, composition order, and the inverse.
#include "sim/core/quaternion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace fluidsound::sim {
namespace {

/// A few products of sines and cosines: rounding only.
constexpr double kRounding = 1e-15;

void expectNear(const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], kRounding) << "component " << k;
}

TEST(Quaternion, QuarterTurnAboutZTakesXToY) {
  // Claim: a right-handed quarter turn about z maps x̂ → ŷ and ŷ → −x̂; the axis's length
  // does not matter. Reference: the right-hand rule.
  const Quaternion q = quaternionFromAxisAngle({0.0, 0.0, 2.0}, std::numbers::pi / 2.0);
  expectNear(rotate(q, {1.0, 0.0, 0.0}), {0.0, 1.0, 0.0});
  expectNear(rotate(q, {0.0, 1.0, 0.0}), {-1.0, 0.0, 0.0});
  expectNear(rotate(q, {0.0, 0.0, 1.0}), {0.0, 0.0, 1.0});
}

TEST(Quaternion, ProductAppliesTheRightFactorFirst) {
  // Claim: (a·b)(v) = a(b(v)). With b a quarter turn about x and a about z: ŷ →b ẑ →a ẑ, while
  // the other order gives ŷ →a −x̂ →b −x̂. Reference: composition by hand.
  const Quaternion a = quaternionFromAxisAngle({0.0, 0.0, 1.0}, std::numbers::pi / 2.0);
  const Quaternion b = quaternionFromAxisAngle({1.0, 0.0, 0.0}, std::numbers::pi / 2.0);
  expectNear(rotate(a * b, {0.0, 1.0, 0.0}), {0.0, 0.0, 1.0});
  expectNear(rotate(b * a, {0.0, 1.0, 0.0}), {-1.0, 0.0, 0.0});
}

TEST(Quaternion, ConjugateUndoesARotation) {
  // Claim: q*·q is the identity on vectors; the zero axis gives the identity rotation.
  const Quaternion q = quaternionFromAxisAngle({1.0, -2.0, 0.5}, 1.3);
  const Vec3 v{0.3, -0.7, 1.1};
  expectNear(rotate(conjugate(q), rotate(q, v)), v);
  EXPECT_EQ(quaternionFromAxisAngle({0.0, 0.0, 0.0}, 1.0), Quaternion{});
}

}  // namespace
}  // namespace fluidsound::sim
