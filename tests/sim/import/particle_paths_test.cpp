// tests/sim/import/particle_paths_test.cpp — a cache particle between frames (sim/particle_paths.h).
#include "sim/particle_paths.h"

#include <gtest/gtest.h>

namespace fluidsound::sim {
namespace {

// Reference: free fall, x(t) = x0 + v0·t + ½·g·t², a quadratic, which the cubic Hermite curve
// through (x0, v0) and (x1, v1) reproduces exactly. Tolerance: float rounding of positions near
// 0.1 m (1e-7 m) and of velocities near 1 m/s (1e-6 m/s).
TEST(ParticlePaths, AFallingParticleFollowsItsParabolaWithinTheFrame) {
  const double g = -9.81, T = 1.0 / 30.0;
  const Vec3f x0{0.1f, 0.13f, 0.08f}, v0{0.2f, -1.0f, 0.0f};
  const auto at = [&](double t) {
    return PathPoint{{static_cast<float>(x0[0] + v0[0] * t), static_cast<float>(x0[1] + v0[1] * t + 0.5 * g * t * t),
                      x0[2]},
                     {v0[0], static_cast<float>(v0[1] + g * t), v0[2]}};
  };
  const PathPoint end = at(T);
  for (double s : {0.0, 0.25, 0.5, 0.8, 1.0}) {
    const PathPoint p = hermitePath(x0, v0, end.position, end.velocity, T, s);
    const PathPoint exact = at(s * T);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(p.position[c], exact.position[c], 1e-7) << s << " " << c;
      EXPECT_NEAR(p.velocity[c], exact.velocity[c], 1e-5) << s << " " << c;
    }
  }
}

// A particle that stops at the surface (v1 = 0) has moved further by mid-frame than the straight
// line says: the curve leaves with the speed it had (v0), the chord would cross at the mean.
TEST(ParticlePaths, AParticleStrikingTheSurfaceKeepsItsSpeedUntilItDoes) {
  const double T = 1.0 / 30.0;
  const Vec3f x0{0.0f, 0.05f, 0.0f}, v0{0.0f, -1.6f, 0.0f}, x1{0.0f, 0.0f, 0.0f}, v1{0.0f, 0.0f, 0.0f};
  // The chord: 1.5 m/s throughout. The curve's velocity: v(s) = 6(s² − s)·(y0 − y1)/T + (3s² − 4s + 1)·v0
  // (v1 = 0), the derivative of the Hermite basis.
  const double s = 0.1;
  const double expected = (6 * s * s - 6 * s) * (0.05 - 0.0) / T + (3 * s * s - 4 * s + 1) * -1.6;
  EXPECT_NEAR(hermitePath(x0, v0, x1, v1, T, s).velocity[1], expected, 1e-5);
  EXPECT_LT(hermitePath(x0, v0, x1, v1, T, 0.0).velocity[1], -1.5f);  // leaves faster than the chord
  EXPECT_LT(hermitePath(x0, v0, x1, v1, T, 0.5).position[1], 0.025f);  // below the chord's midpoint
}

}  // namespace
}  // namespace fluidsound::sim
