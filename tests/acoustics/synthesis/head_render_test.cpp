// tests/acoustics/synthesis/head_render_test.cpp — a binaural head's two ears (head_render.h,
// synthesis_stage.h) through the MIT KEMAR set as Debian ships it: bubbles 90° to the left of a
// head reach the ears with the set's own interaural time difference (within the 50 µs)
// and level difference at 2 kHz; a bubble straight ahead reaches both ears alike (within the
// issue's 0.5 dB); the FFT convolution equals the direct sum; the render is the same for any
// thread count (issue 20; docs/binaural.md).
#include "acoustics/synthesis/head_render.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "acoustics/binaural/hrir_convolution.h"
#include "acoustics/bubble/minnaert.h"
#include "acoustics/synthesis/synthesis_stage.h"
#include "io/hrir_file.h"

namespace fluidsound::acoustics {
namespace {

constexpr double kRate = 44100.0;  // the KEMAR set's own rate: no resampling in these tests

const HrirTable& kemar() {
  static const HrirTable table = io::readHrirTable(io::defaultHrirFile(), kRate);
  return table;
}

/// A head at the origin of a Y-up scene, facing +z: its left ear is towards +x (left = up × facing).
ListenerHead headFacingZ() { return {"head", {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {0.0, 1.0, 0.0}}; }

/// A bubble 10 cm deep at `position`, heard with transfer 1 by the one listener.
BubbleTrack bubbleAt(double radius, double birth, const Vec3& position) {
  BubbleTrack b;
  b.radius = radius;
  b.birth = birth;
  for (double t : {birth, birth + 1.0}) b.track.push_back({t, 0.1, {1.0}, position});
  return b;
}

BubbleTrackSet oneListener(std::vector<BubbleTrack> bubbles, double duration) {
  BubbleTrackSet set;
  set.sampleRate = kRate;
  set.duration = duration;
  set.listeners = {"head"};
  set.heads = {headFacingZ()};
  set.bubbles = std::move(bubbles);
  return set;
}

SynthesisSettings settingsFor(const BubbleTrackSet& set) {
  SynthesisSettings s;
  s.sampleRate = set.sampleRate;
  s.duration = set.duration;
  return s;
}

HeadSignals render(const BubbleTrackSet& set) {
  const SynthesisSettings s = settingsFor(set);
  return renderHead(set, 0, set.heads[0], kemar(), s, static_cast<std::int64_t>(std::ceil(*set.duration * kRate)));
}

double rms(const std::vector<float>& x) {
  double sum = 0.0;
  for (float v : x) sum += static_cast<double>(v) * v;
  return std::sqrt(sum / static_cast<double>(x.size()));
}

double levelDifferenceDb(const HeadSignals& ears) { return 20.0 * std::log10(rms(ears.left) / rms(ears.right)); }

/// Σ_n right[n] · left[n − lag].
double correlation(const std::vector<float>& left, const std::vector<float>& right, long lag) {
  double sum = 0.0;
  for (long n = std::max(0L, lag); n < static_cast<long>(right.size()) && n - lag < static_cast<long>(left.size()); ++n)
    sum += static_cast<double>(right[n]) * left[n - lag];
  return sum;
}

/// The lag [s] by which the right ear follows the left: the cross-correlation's peak within
/// ±1.5 ms, refined by a parabola (the same estimator as interauralTimeDifference).
double renderedTimeDifference(const HeadSignals& ears) {
  const long span = std::lround(1.5e-3 * kRate);
  long best = 0;
  double peak = -1e300;
  for (long lag = -span; lag <= span; ++lag)
    if (const double c = correlation(ears.left, ears.right, lag); c > peak) peak = c, best = lag;
  const double before = correlation(ears.left, ears.right, best - 1), after = correlation(ears.left, ears.right, best + 1);
  const double curvature = before - 2.0 * peak + after;
  return (best + (curvature < 0.0 ? 0.5 * (before - after) / curvature : 0.0)) / kRate;
}

/// 60 bubbles of 0.3–3 mm (Minnaert 11 kHz down to 1.1 kHz) born over 0.3 s at `position`: a
/// broadband cloud, so the ears' cross-correlation has one clear peak at the pair's time difference.
std::vector<BubbleTrack> cloudAt(const Vec3& position) {
  std::vector<BubbleTrack> cloud;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> logRadius(std::log(0.3e-3), std::log(3e-3)), birth(0.0, 0.3);
  for (int i = 0; i < 60; ++i) cloud.push_back(bubbleAt(std::exp(logRadius(random)), birth(random), position));
  return cloud;
}

// Reference: the KEMAR set's own ITD for the measured direction at 90° left (its pair's
// cross-correlation peak, interauralTimeDifference; 722 µs). Tolerance: the 50 µs; the
// render convolves with that very pair, so what is left is the one-sample rounding of delays
// (11 µs) and the cloud's own correlation.
TEST(HeadRender, ABubbleCloudToTheLeftReachesTheEarsWithTheSetsTimeDifference) {
  const HeadSignals ears = render(oneListener(cloudAt({2.0, 0.0, 0.0}), 0.5));
  EXPECT_EQ(ears.directions, 1u);
  const double expected = interauralTimeDifference(kemar(), nearestDirection(kemar(), {0.0, 1.0, 0.0}));
  const double rendered = renderedTimeDifference(ears);
  std::printf("rendered ITD %.1f µs, the set's %.1f µs\n", rendered * 1e6, expected * 1e6);
  EXPECT_GT(rendered, 0.0);  // the left ear hears first
  EXPECT_NEAR(rendered, expected, 50e-6) << "rendered " << rendered * 1e6 << " µs, set " << expected * 1e6 << " µs";
  // And mirrored: to the right (−x), the right ear leads by as much.
  const HeadSignals mirrored = render(oneListener(cloudAt({-2.0, 0.0, 0.0}), 0.5));
  EXPECT_NEAR(renderedTimeDifference(mirrored), -expected, 50e-6);
}

// Reference: the set's level difference at the bubble's frequency (interauralLevelDifference;
// +6.6 dB at 2 kHz for KEMAR, head shadow 6–10 dB: Shaw 1974). Tolerance 1 dB: the bubble's
// spectrum has a width (its damping, about 3 % of 2 kHz) over which the pair's ratio varies.
TEST(HeadRender, ABubbleAt2kHzToTheLeftIsLouderInTheLeftEarAsTheSetSays) {
  const LiquidProperties water;
  const double radius = 3.26 / 2000.0;  // Minnaert: f·R ≈ 3.26 m/s in water at 1 atm
  const double frequency = basicMinnaertFrequency(radius, water);
  ASSERT_NEAR(frequency, 2000.0, 100.0);
  const HeadSignals ears = render(oneListener({bubbleAt(radius, 0.01, {2.0, 0.0, 0.0})}, 0.3));
  const double expected = interauralLevelDifference(kemar(), nearestDirection(kemar(), {0.0, 1.0, 0.0}), frequency);
  const double rendered = levelDifferenceDb(ears);
  std::printf("rendered ILD at %.0f Hz %.2f dB, the set's %.2f dB\n", frequency, rendered, expected);
  EXPECT_GT(rendered, 3.0);
  EXPECT_NEAR(rendered, expected, 1.0) << "set " << expected << " dB";
}

// Reference: the 0.5 dB for a source straight ahead. And the set's gain: below 500 Hz a
// head changes the pressure by about 1 dB or less (Shaw 1974), so a 300 Hz bubble ahead reaches
// each ear at the head centre's level within 1.5 dB (freeFieldGain).
TEST(HeadRender, ABubbleStraightAheadReachesBothEarsAlikeAtTheCentresLevel) {
  for (double radius : {1.63e-3, 0.8e-3, 11e-3}) {
    BubbleTrackSet set = oneListener({bubbleAt(radius, 0.01, {0.0, 0.0, 2.0})}, 0.3);
    const HeadSignals ears = render(set);
    std::printf("ahead, R = %.2f mm: left − right %.3f dB\n", radius * 1e3, levelDifferenceDb(ears));
    EXPECT_NEAR(levelDifferenceDb(ears), 0.0, 0.5) << "radius " << radius;
    if (radius > 10e-3) {
      const SynthesisResult centre = synthesize(set, settingsFor(set));
      const double gainDb = 20.0 * std::log10(rms(ears.left) / rms(centre.channels[0]));
      std::printf("ahead, R = %.2f mm: ear − centre %.2f dB\n", radius * 1e3, gainDb);
      EXPECT_NEAR(gainDb, 0.0, 1.5);
    }
  }
}

TEST(HeadRender, TheFftConvolutionEqualsTheDirectSum) {
  std::mt19937_64 random(3);
  std::normal_distribution<float> noise;
  std::vector<float> signal(20000, 0.0f), response(512);
  for (std::size_t i = 0; i < signal.size(); ++i)
    if ((i / 3000) % 2 == 0) signal[i] = noise(random);  // silent stretches are skipped: still equal
  for (float& r : response) r = noise(random);
  for (std::size_t delay : {0u, 7u}) {
    std::vector<double> fast(18000, 0.0), direct(18000, 0.0);
    addConvolution(signal, response, delay, 0.5, fast);
    addConvolutionDirect(signal, response, delay, 0.5, direct);
    double largest = 0.0, error = 0.0;
    for (std::size_t n = 0; n < fast.size(); ++n)
      largest = std::max(largest, std::fabs(direct[n])), error = std::max(error, std::fabs(fast[n] - direct[n]));
    EXPECT_LT(error, 1e-9 * largest) << "delay " << delay;
  }
}

TEST(HeadRender, IsBitIdenticalForOneAndTwoThreads) {
  BubbleTrackSet set = oneListener(cloudAt({2.0, 0.0, 0.0}), 0.4);
  for (std::size_t i = 0; i < set.bubbles.size(); i += 2)  // and a second direction, ahead
    for (TrackSample& s : set.bubbles[i].track) s.position = Vec3{0.3, 0.0, 2.0};
  HeadSignals one, two;
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
    one = render(set);
  }
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
    two = render(set);
  }
  EXPECT_EQ(one.directions, 2u);
  EXPECT_EQ(one.left, two.left);
  EXPECT_EQ(one.right, two.right);
}

TEST(HeadRender, TheStageWritesTwoChannelsPerHeadAndKeepsPointListeners) {
  BubbleTrackSet set = oneListener(cloudAt({2.0, 0.0, 0.0}), 0.3);
  set.listeners = {"near", "head"};
  for (BubbleTrack& b : set.bubbles)
    for (TrackSample& s : b.track) s.transfer = {0.5, 1.0};
  EXPECT_EQ(outputChannelNames(set), (std::vector<std::string>{"near", "head.left", "head.right"}));
  StageObserver quiet;
  SynthesisOptions options;
  EXPECT_THROW(synthesize(set, options, quiet), std::invalid_argument);  // no responses given
  options.headResponses = &kemar();
  const SynthesisStageResult result = synthesize(set, options, quiet);
  ASSERT_EQ(result.channels.size(), 3u);
  BubbleTrackSet plain = set;
  plain.heads.clear();
  EXPECT_EQ(result.channels[0], synthesize(plain, options, quiet).channels[0]);
  EXPECT_EQ(result.headDirections, 1u);
  EXPECT_GT(rms(result.channels[1]), rms(result.channels[2]));  // the left ear faces the bubbles
}

}  // namespace
}  // namespace fluidsound::acoustics
