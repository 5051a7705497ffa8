// Tests of acoustics/modal/sound_occlusion.h: Maekawa's barrier attenuation, the detour over a
// bounding sphere, and the factors per mode of a path that an occluder crosses.
#include "acoustics/modal/sound_occlusion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fluidsound::acoustics {
namespace {

// Maekawa's chart as 10·log₁₀(3 + 20N): 4.77 dB at grazing (N = 0), 13.6 dB at N = 1, capped at
// 24 dB (N ≈ 12). Reference: the formula, to rounding.
TEST(SoundOcclusion, BarrierAttenuationFollowsMaekawa) {
  EXPECT_NEAR(barrierAttenuationDb(0.0, 1000.0, 343.2), 10.0 * std::log10(3.0), 1e-12);
  EXPECT_NEAR(barrierAttenuationDb(343.2 / 2000.0, 1000.0, 343.2), 10.0 * std::log10(23.0), 1e-12);  // N = 1
  EXPECT_DOUBLE_EQ(barrierAttenuationDb(10.0, 20000.0, 343.2), 24.0);
}

// Over a sphere of radius 0.5 m midway on a 2 m path, through its centre: 2·√(1 + 0.25) − 2 =
// 0.2361 m; passing 0.3 m off its centre, over the near rim (0.2 m further out): 2·√(1 + 0.04) − 2;
// missing it: 0. And the factor of a crossed occluder at 1 kHz is 10^(−A/20); one that is not
// crossed, or the body itself, leaves the path alone.
TEST(SoundOcclusion, DetourOverTheSphereAndTheFactors) {
  const Eigen::Vector3d a(-1.0, 0.0, 0.0), b(1.0, 0.0, 0.0), centre = Eigen::Vector3d::Zero();
  EXPECT_NEAR(detourOverSphere(a, b, centre, 0.5), 2.0 * std::sqrt(1.25) - 2.0, 1e-12);
  EXPECT_NEAR(detourOverSphere(a, b, Eigen::Vector3d(0.0, 0.3, 0.0), 0.5), 2.0 * std::sqrt(1.04) - 2.0, 1e-12);
  EXPECT_EQ(detourOverSphere(a, b, Eigen::Vector3d(0.0, 0.7, 0.0), 0.5), 0.0);
  const std::vector<Occluder> occluders = {
      {3, centre, 0.5, [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return true; }},
      {4, centre, 0.5, [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return false; }}};
  const std::vector<double> f = occlusionFactors(occluders, 0, a, b, {1000.0}, 343.2);
  const double expected = std::pow(10.0, -barrierAttenuationDb(2.0 * std::sqrt(1.25) - 2.0, 1000.0, 343.2) / 20.0);
  EXPECT_NEAR(f[0], expected, 1e-12);
  EXPECT_EQ(occlusionFactors(occluders, 3, a, b, {1000.0}, 343.2)[0], 1.0) << "a body does not shadow itself";
}

}  // namespace
}  // namespace fluidsound::acoustics
