// Tests of io/loudness.h against the EBU Tech 3341 test signals (generated here): the
// integrated loudness of gated sine sequences, the true peak between samples, every listener
// weighted alike, and the normalisation gain under a true-peak ceiling.
#include "io/loudness.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/task_arena.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace fluidsound::io {
namespace {

constexpr double kRate = 48000.0;

/// A sine of `frequency` [Hz] whose amplitude is `dbfs` for `seconds`, per segment, one after the
/// other (the phase runs on across segments), starting at phase `phase` [rad].
std::vector<float> sineSegments(double frequency,
                                const std::vector<std::pair<double, double>>& dbfsSeconds,
                                double phase = 0.0) {
  std::vector<float> x;
  for (const auto& [dbfs, seconds] : dbfsSeconds) {
    const double amplitude = std::pow(10.0, dbfs / 20.0);
    const auto n = static_cast<std::size_t>(std::lround(seconds * kRate));
    for (std::size_t i = 0; i < n; ++i) {
      const double t = static_cast<double>(x.size()) / kRate;
      x.push_back(
          static_cast<float>(amplitude * std::sin(2 * std::numbers::pi * frequency * t + phase)));
    }
  }
  return x;
}

std::vector<std::vector<float>> stereo(const std::vector<float>& x) { return {x, x}; }

// Claim: integrated loudness per ITU-R BS.1770-4 with its two gates. Reference: EBU Tech 3341
// (2016) Table 1, stereo 1 kHz sines: case 1 (−23 dBFS, 20 s), case 2 (−33 dBFS, 20 s), case 3
// (−36/−23/−36 dBFS for 10/60/10 s: the relative gate drops the quiet parts), case 4
// (−72/−36/−23/−36/−72 for 10/10/60/10/10 s: the absolute gate too), case 5 (−26/−20/−26 for
// 20/20.1/20 s: the loud middle and quiet ends mix, 10·log10 of the mean power). Expected
// −23.0 LUFS in cases 1, 3, 4, 5 and −33.0 in case 2. Tolerance ±0.1 LU: Tech 3341's
// requirement for a meter in "EBU Mode".
struct Tech3341Case {
  const char* name;
  std::vector<std::pair<double, double>> segments;  ///< (dBFS, seconds) one after the other
  double expectedLufs;
};

class LoudnessTech3341 : public ::testing::TestWithParam<Tech3341Case> {};

TEST_P(LoudnessTech3341, IntegratedLoudnessWithinATenthOfAnLU) {
  const Tech3341Case& c = GetParam();
  const auto channels = stereo(sineSegments(1000.0, c.segments));
  const LoudnessMeasurement m = measureLoudness(channels, kRate);
  ASSERT_TRUE(m.integratedLufs.has_value());
  EXPECT_NEAR(*m.integratedLufs, c.expectedLufs, 0.1);
}

INSTANTIATE_TEST_SUITE_P(
    Table1, LoudnessTech3341,
    ::testing::Values(Tech3341Case{"case1", {{-23, 20}}, -23.0},
                      Tech3341Case{"case2", {{-33, 20}}, -33.0},
                      Tech3341Case{"case3", {{-36, 10}, {-23, 60}, {-36, 10}}, -23.0},
                      Tech3341Case{
                          "case4", {{-72, 10}, {-36, 10}, {-23, 60}, {-36, 10}, {-72, 10}}, -23.0},
                      Tech3341Case{"case5", {{-26, 20}, {-20, 20.1}, {-26, 20}}, -23.0}),
    [](const ::testing::TestParamInfo<Tech3341Case>& info) { return info.param.name; });

// Claim: the true peak is the peak of the continuous signal, not of its samples. Reference: a
// sine at fs/4 with 45° phase has every sample at ±A·sin 45° (3.01 dB below its crest A), the
// signal of EBU Tech 3341's true-peak cases 15–18 (sines at fs/4 … fs/8 with phases that put the
// samples off the crests); at A = −6 dBFS the expected true peak is −6.0 dBTP. Tolerance
// +0.2/−0.4 dB: Tech 3341's requirement for true-peak meters (an interpolator may read a little
// low). The sample peak, −9.03 dBFS, is 3 dB outside that band, so a meter reading samples fails.
TEST(Loudness, ReadsTheTruePeakBetweenSamples) {
  const auto channels = stereo(sineSegments(kRate / 4, {{-6.0, 2.0}}, std::numbers::pi / 4));
  float samplePeak = 0.0f;
  for (float v : channels[0]) samplePeak = std::max(samplePeak, std::abs(v));
  EXPECT_NEAR(20 * std::log10(samplePeak), -6.0 - 3.0103, 0.01) << "the test signal itself";
  const LoudnessMeasurement m = measureLoudness(channels, kRate);
  EXPECT_LE(m.truePeakDbtp, -6.0 + 0.2);
  EXPECT_GE(m.truePeakDbtp, -6.0 - 0.4);
}

// Claim: every channel counts with weight 1 (loudness.h: listeners are not loudspeakers).
// Reference: a 1 kHz sine at −23 dBFS alone in one channel of a six-channel render is −26.0 LUFS
// whichever channel holds it (half the power of Tech 3341 case 1's two channels: −3.01 LU);
// libebur128's default map would drop channel 3 (LFE: −∞) and raise 4 and 5 by 1.5 dB
// (surround weight 1.41). Tolerance ±0.1 LU as in Tech 3341.
TEST(Loudness, WeighsEveryListenerAlike) {
  const std::vector<float> sine = sineSegments(1000.0, {{-23, 2}});
  for (std::size_t lit = 0; lit < 6; ++lit) {
    std::vector<std::vector<float>> channels(6, std::vector<float>(sine.size(), 0.0f));
    channels[lit] = sine;
    const LoudnessMeasurement m = measureLoudness(channels, kRate);
    ASSERT_TRUE(m.integratedLufs.has_value()) << "channel " << lit;
    EXPECT_NEAR(*m.integratedLufs, -23.0 - 3.0103, 0.1) << "channel " << lit;
  }
}

// Claim: the measurement is the same bits for any thread count (the true-peak meters of the
// channels run in parallel, each on the same samples in the same order). Reference: one thread.
TEST(Loudness, IsTheSameForAnyThreadCount) {
  std::vector<std::vector<float>> channels;
  for (int c = 0; c < 5; ++c)
    channels.push_back(sineSegments(300.0 + 200.0 * c, {{-20.0 - c, 2.0}}, 0.3 * c));
  LoudnessMeasurement serial;
  oneapi::tbb::task_arena(1).execute([&] { serial = measureLoudness(channels, kRate); });
  const LoudnessMeasurement parallel = measureLoudness(channels, kRate);
  ASSERT_TRUE(serial.integratedLufs && parallel.integratedLufs);
  EXPECT_EQ(*serial.integratedLufs, *parallel.integratedLufs);
  EXPECT_EQ(serial.truePeakDbtp, parallel.truePeakDbtp);
}

// Claim: silence and records shorter than one 400 ms gating block have no integrated loudness
// (BS.1770-4: loudness is the mean over complete blocks), and silence has a true peak of −∞.
TEST(Loudness, SilenceAndShortRecordsHaveNoIntegratedLoudness) {
  const LoudnessMeasurement silent =
      measureLoudness(stereo(std::vector<float>(48000, 0.0f)), kRate);
  EXPECT_FALSE(silent.integratedLufs.has_value());
  EXPECT_TRUE(std::isinf(silent.truePeakDbtp) && silent.truePeakDbtp < 0);
  const LoudnessMeasurement shortSine =
      measureLoudness(stereo(sineSegments(1000.0, {{-23, 0.3}})), kRate);
  EXPECT_FALSE(shortSine.integratedLufs.has_value());
}

// Claim: the normalisation gain reaches the target when the true peak allows it and is lowered to
// the ceiling when not (loudness.h). Reference: Tech 3341 case 1 (−23 LUFS, sine crest −23 dBTP)
// raised to −14 LUFS needs +9 dB and leaves the crest at −14 dBTP, under a −1 dBTP ceiling; raised
// to −0.5 LUFS it would need +22.5 dB and put the crest at −0.5 dBTP, so the gain is cut to the
// ceiling's +22 dB (−1.0 LUFS). Measured back after the gain: within Tech 3341's ±0.1 LU and the
// true-peak meter's +0.2/−0.4 dB.
TEST(Loudness, NormalisationGainMeetsTargetUnderTheTruePeakCeiling) {
  const auto channels = stereo(sineSegments(1000.0, {{-23, 5}}));
  const LoudnessMeasurement m = measureLoudness(channels, kRate);
  const auto reached = loudnessNormalisationGain(m, {-14.0, -1.0});
  ASSERT_TRUE(reached.has_value());
  EXPECT_FALSE(reached->limitedByTruePeak);
  EXPECT_NEAR(reached->gainDecibels, 9.0, 0.1);
  const LoudnessMeasurement after =
      measureLoudness(channels, kRate, std::pow(10.0, reached->gainDecibels / 20));
  EXPECT_NEAR(*after.integratedLufs, -14.0, 0.1);

  const auto limited = loudnessNormalisationGain(m, {-0.5, -1.0});
  ASSERT_TRUE(limited.has_value());
  EXPECT_TRUE(limited->limitedByTruePeak);
  const LoudnessMeasurement capped =
      measureLoudness(channels, kRate, std::pow(10.0, limited->gainDecibels / 20));
  EXPECT_LE(capped.truePeakDbtp, -1.0 + 0.2);
  EXPECT_GE(capped.truePeakDbtp, -1.0 - 0.4);
  EXPECT_NEAR(*capped.integratedLufs, -1.0, 0.1)
      << "the ceiling's gain, 0.5 LU short of the target";

  EXPECT_FALSE(loudnessNormalisationGain(LoudnessMeasurement{}, {}).has_value())
      << "no loudness, no gain";
}

}  // namespace
}  // namespace fluidsound::io
