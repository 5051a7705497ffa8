// tests/acoustics/playback/sample_playback_test.cpp — impacts played as one-shots and rubbing as
// loops: where, how loud, and silence outside their time (shared solids.md T9: "a loop stops when
// F_t < 1 N").
#include "acoustics/playback/sample_playback.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fluidsound::acoustics {
namespace {

RecordedSound ramp(std::size_t n) {
  RecordedSound s;
  for (std::size_t i = 0; i < n; ++i) s.samples.push_back(static_cast<float>(i + 1));
  return s;
}

// An impact at 0.5 ms plays the recording from sample 24 at 10^(−6.02/20) = ½; a second one 4 ms
// later and quieter is dropped (within the 10 ms minimum interval), a louder one is not.
TEST(SamplePlayback, ImpactsPlayTheRecordingAtTheirTimeAndGain) {
  const RecordedSound sound = ramp(100);
  const double half = -20.0 * std::log10(2.0);
  const ImpactTrigger quieter[] = {{0.0005, half}, {0.0045, half - 3.0}};
  const std::vector<float> out = playImpacts(sound, quieter, 1000);
  EXPECT_EQ(out[23], 0.0f);
  EXPECT_NEAR(out[24], 0.5f, 1e-6f);
  EXPECT_NEAR(out[24 + 99], 50.0f, 1e-4f);
  EXPECT_EQ(out[24 + 100], 0.0f);
  const ImpactTrigger louder[] = {{0.0005, half}, {0.0045, 0.0}};
  EXPECT_NEAR(playImpacts(sound, louder, 1000)[216], 1.0f, 1e-6f);  // the second from 0.0045·48000 = 216
}

// A slide active from 10 ms to 30 ms of 1 ms substeps (the friction force above 1 N there, below it
// before and after): silent outside, faded in over 5 ms from the recording's start, looped, and
// faded out after 30 ms.
TEST(SamplePlayback, LoopPlaysOnlyWhileItsContactIsActive) {
  RecordedSound sound;
  sound.samples.assign(48, 1.0f);  // 1 ms of ones: the loop wraps 20 times
  std::vector<LoopSubstep> substeps;
  for (int k = 1; k <= 50; ++k) substeps.push_back({k * 1e-3, k > 10 && k <= 30, 0.0});
  const std::vector<float> out = playLoop(sound, substeps, 1e-3, 48 * 60);
  for (std::size_t n = 0; n < 480; ++n) ASSERT_EQ(out[n], 0.0f) << n;
  EXPECT_GT(out[481], 0.0f);
  EXPECT_LT(out[481], 0.01f);  // fading in
  for (std::size_t n = 480 + 240; n < 1440; ++n) ASSERT_NEAR(out[n], 1.0f, 1e-6f) << n;
  EXPECT_LT(out[1440 + 120], 0.6f);  // fading out
  for (std::size_t n = 1440 + 241; n < out.size(); ++n) ASSERT_EQ(out[n], 0.0f) << n;
}

}  // namespace
}  // namespace fluidsound::acoustics
