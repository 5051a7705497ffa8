// tests/acoustics/playback/collision_loudness_test.cpp — the sample-playback paper's loudness model
// against shared solids.md T9.
#include "acoustics/playback/collision_loudness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace fluidsound::acoustics {
namespace {

// T9: ΔV_imp(v_n = v⁰/2, m = m⁰) = 20·log10 2 = 6.02 dB quieter; the mass enters as its square
// root (a quarter of the mass: 6.02 dB too). Exact formulas: 1e-12 dB.
TEST(CollisionLoudness, ImpactHalfAsFastIsSixDecibelsQuieter) {
  EXPECT_NEAR(impactGainDb(1.0, 0.5, 2.0, 0.5), -20.0 * std::log10(2.0), 1e-12);
  EXPECT_NEAR(impactGainDb(2.0, 0.125, 2.0, 0.5), -20.0 * std::log10(2.0), 1e-12);
  EXPECT_EQ(impactGainDb(4.0, 0.5, 2.0, 0.5), 0.0);  // louder than the recording: clamped, never boosted
}

// T9: ΔV_sli with F_n and v_t both halved = 6.02 dB (the power, F_n·v, a quarter).
TEST(CollisionLoudness, RubbingAtAQuarterOfThePowerIsSixDecibelsQuieter) {
  EXPECT_NEAR(rubbingGainDb(5.0, 0.25, 10.0, 0.5), -20.0 * std::log10(2.0), 1e-12);
  EXPECT_EQ(rubbingGainDb(20.0, 1.0, 10.0, 0.5), 0.0);
  EXPECT_THROW(rubbingGainDb(1.0, 1.0, 0.0, 1.0), std::invalid_argument);
}

// Eq. 3, and a static body (mass 0 given) leaves the other's mass.
TEST(CollisionLoudness, ReducedMass) {
  EXPECT_DOUBLE_EQ(reducedMass(2.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(reducedMass(0.0, 3.0), 3.0);
  EXPECT_DOUBLE_EQ(reducedMass(3.0, 0.0), 3.0);
}

}  // namespace
}  // namespace fluidsound::acoustics
