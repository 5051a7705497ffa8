// tests/acoustics/modal/stick_slip_test.cpp — stick–slip breaks (after the friction paper, shared
// solids.md §1.3): their rate goes as v² (patch a = a₁/v crossed at v), their impulses carry the
// friction's, and a contact that sticks or rolls makes none.
#include "acoustics/modal/stick_slip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fluidsound::acoustics {
namespace {

std::vector<RubbingSample> sliding(double speed, double seconds, bool rolling = false) {
  std::vector<RubbingSample> s;
  for (int i = 1; i <= static_cast<int>(std::lround(seconds * 1000)); ++i) {
    RubbingSample sample{i * 1e-3, 10.0, speed};
    sample.friction = {-3.0, 0.0, 0.0};  // 3 N against the motion along +x
    sample.rolling = rolling;
    s.push_back(sample);
  }
  return s;
}

// a₁ = 3 mm: at 0.5 m/s a break every a₁/v² = 12 ms, at 1 m/s every 3 ms (exactly, from a whole
// number of patches; the last partial patch is not released), each with 3 N × the interval.
TEST(StickSlip, BreaksComeAtTheSquareOfTheSpeedAndCarryTheFriction) {
  for (double v : {0.5, 1.0}) {
    const std::vector<ModalImpact> slips = stickSlipImpacts(sliding(v, 0.6), {});
    const double interval = 3e-3 / (v * v);
    ASSERT_GE(slips.size(), 2u);
    EXPECT_NEAR(static_cast<double>(slips.size()), std::floor(0.6 / interval + 1e-9), 1.0) << v;
    for (std::size_t i = 1; i < slips.size(); ++i)
      EXPECT_NEAR(slips[i].time - slips[i - 1].time, interval, 1e-9) << v << " " << i;
    for (const ModalImpact& slip : slips) EXPECT_NEAR(slip.impulse.x(), -3.0 * interval, 1e-9) << v;
  }
}

// A spread of the patches (a rough surface) keeps the impulses' sum: the friction's over the time
// up to the last break, whatever the breaks' times.
TEST(StickSlip, RoughPatchesKeepTheFrictionsImpulse) {
  StickSlipSettings rough;
  rough.patchSpread = 0.3;
  const std::vector<ModalImpact> slips = stickSlipImpacts(sliding(0.7, 0.5), rough);
  ASSERT_GT(slips.size(), 10u);
  double sum = 0.0;
  for (const ModalImpact& slip : slips) sum += slip.impulse.x();
  EXPECT_NEAR(sum, -3.0 * slips.back().time, 1e-9);
  EXPECT_EQ(stickSlipImpacts(sliding(0.7, 0.5), rough).size(), slips.size());  // deterministic
}

// A contact speeding up from a crawl (a box that starts to slide: 2 m/s², from 1 mm/s to 1 m/s in
// 0.5 s) breaks at the patch of its speed now, a₁/v, and releases at most the friction over one
// such patch, F·a₁/v², not the friction of its whole slow start; each slip lasts slipShare of
// its patch's time (a half-sine pulse, StickSlipSettings::slipShare). Reference: the bound
// itself, per slip, to rounding.
TEST(StickSlip, AcceleratingContactReleasesAtMostOnePatchOfFriction) {
  std::vector<RubbingSample> ramp;
  for (int i = 1; i <= 500; ++i) {
    RubbingSample sample{i * 1e-3, 10.0, 1e-3 + 2.0 * i * 1e-3};
    sample.friction = {-3.0, 0.0, 0.0};
    ramp.push_back(sample);
  }
  const std::vector<ModalImpact> slips = stickSlipImpacts(ramp, {});
  ASSERT_GT(slips.size(), 20u);
  for (const ModalImpact& slip : slips) {
    const double v = 1e-3 + 2.0 * std::ceil(slip.time * 1e3 - 1e-9) * 1e-3;  // its substep's speed
    const double patchTime = 3e-3 / (v * v);
    EXPECT_LE(std::abs(slip.impulse.x()), 3.0 * patchTime * (1.0 + 1e-9)) << slip.time;
    EXPECT_NEAR(slip.contactDuration, 0.1 * patchTime, 1e-12) << slip.time;
  }
  // Unbounded, the first slip (at ~0.11 s, where the slid t² reaches a₁/v) would carry the 3 N
  // of the whole time before it; the bound at its speed (0.23 m/s) leaves about half of that.
  EXPECT_LT(std::abs(slips.front().impulse.x()), 0.6 * 3.0 * slips.front().time);
}

TEST(StickSlip, StickingOrRollingMakesNoBreaks) {
  EXPECT_TRUE(stickSlipImpacts(sliding(1e-7, 0.5), {}).empty());
  EXPECT_TRUE(stickSlipImpacts(sliding(1.0, 0.5, true), {}).empty());
}

}  // namespace
}  // namespace fluidsound::acoustics
