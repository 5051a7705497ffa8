// Tests of acoustics/analysis/centroid_prediction.h: the energy and centroid predicted from bubble tracks
// against closed forms and against the synthesizer's render measured by power_spectrum.h.
#include "acoustics/analysis/centroid_prediction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "acoustics/bubble/bubble_oscillator.h"
#include "acoustics/analysis/damped_sine_spectrum.h"
#include "acoustics/bubble/depth_shift.h"
#include "acoustics/analysis/power_spectrum.h"
#include "support/deep_bubble.h"

namespace fluidsound::acoustics {
namespace {

constexpr double kSampleRate = 48000.0;
constexpr FrequencyBand kAudible{20.0, 20000.0};

SynthesisSettings defaultSettings() {
  SynthesisSettings s;
  s.sampleRate = kSampleRate;
  return s;
}

using test::dampedFrequency;
using test::deepConstants;

/// A bubble held at constant depth and transfer (one track sample per frame over 0.2 s).
BubbleTrack steadyBubble(double radius, double birth, double depth, std::vector<double> transfer) {
  BubbleTrack b;
  b.radius = radius;
  b.birth = birth;
  for (int k = 0; k <= 6; ++k) b.track.push_back({birth + k / 30.0, depth, transfer, std::nullopt});
  return b;
}

struct Measured {
  double centroid = 0.0;
  double energy = 0.0;  ///< ∫ p² dt within the band [Pa²·s]
};

Measured measure(const std::vector<float>& x, const FrequencyBand& band) {
  const PowerSpectrum s = welchPowerSpectrum(x, kSampleRate, 4096);
  Measured m;
  m.centroid = spectralCentroid(s, band);
  for (std::size_t k = 0; k < s.power.size(); ++k)
    if (s.frequency(k) >= band.low && s.frequency(k) <= band.high)
      m.energy += s.power[k] * s.binWidth;
  m.energy *= static_cast<double>(x.size()) / kSampleRate;  // mean power × duration
  return m;
}

// Claim: for one deep bubble born on a sample the prediction is A² times the band energy of the
// unit sampled damped sine at the bubble's damped frequency and decay rate, at that sine's band
// centroid (damped_sine_spectrum.h, tested against an FFT there); for R = 1 mm in 20 Hz … 20 kHz
// the centroid lies below the ringing frequency (the line's flat low tail, centroid_prediction.h).
// Reference: DampedSineSpectrum::inBand. Tolerance 1e-9 relative: the 32 energy points sum the
// same value; the 90 dB cut-off leaves 10⁻⁹ of the energy out.
TEST(CentroidPrediction, OneDeepBubbleIsItsDampedSineLine) {
  const SynthesisSettings s = defaultSettings();
  const OscillatorConstants c = deepConstants(1e-3, s);
  BubbleTrackSet set;
  set.bubbles.push_back({1e-3, 0.01, std::nullopt, {}, {}});
  const std::vector<PredictedSpectrum> p = predictedSpectra(set, s, kAudible);
  ASSERT_EQ(p.size(), 1u);
  const BandSpectrum line =
      DampedSineSpectrum(kSampleRate)
          .inBand(2.0 * std::numbers::pi * dampedFrequency(c), c.decayRate, kAudible);
  const double energy = c.amplitude * c.amplitude * line.energy;
  EXPECT_NEAR(p[0].bandEnergy, energy, 2e-9 * energy);
  EXPECT_NEAR(p[0].centroid, line.centroid, 1e-9 * line.centroid);
  EXPECT_LT(p[0].centroid, 0.995 * dampedFrequency(c))
      << "the low tail pulls the centroid below the ringing frequency";
  EXPECT_EQ(p[0].bubbles, 1);
}

// Claim: the prediction matches the render of single bubbles, deep (R = 0.5, 1, 3 mm) and near
// the surface (R = 1 mm at h = 2R: Strasberg raises f by 15.8 %, physics.md T3), in centroid and
// band energy. Reference: welchPowerSpectrum of synthesize() over 20 Hz … 20 kHz. Tolerance 0.1 %
// for both: what the prediction neglects for one steady bubble is the birth between samples (a
// phase under one sample) and the float samples (rounding ~10⁻⁷); the Welch estimate is exact in
// energy (Parseval) and moves the centroid only through the leakage across the band edges.
TEST(CentroidPrediction, MatchesTheRenderOfSingleBubbles) {
  const SynthesisSettings s = defaultSettings();
  struct Case {
    double radius, depth;
  };
  for (const Case k : {Case{0.5e-3, 1.0}, Case{1e-3, 1.0}, Case{3e-3, 1.0}, Case{1e-3, 2e-3}}) {
    BubbleTrackSet set;
    set.bubbles.push_back(steadyBubble(k.radius, 0.01, k.depth, {1.0}));
    const Measured m = measure(synthesize(set, s).channels.at(0), kAudible);
    const PredictedSpectrum p = predictedSpectra(set, s, kAudible).at(0);
    EXPECT_NEAR(m.centroid, p.centroid, 0.001 * p.centroid)
        << "R = " << k.radius << " m, h = " << k.depth << " m";
    EXPECT_NEAR(m.energy, p.bandEnergy, 0.001 * p.bandEnergy)
        << "R = " << k.radius << " m, h = " << k.depth << " m";
  }
}

// Claim: a bubble held at h = 2R rings at its Strasberg-shifted frequency, ω₀·S(h) with
// S = (1 − x − x⁴)^(−1/2), x = R/2h (physics.md §5; ×1.15772 at h = 2R, T3), damped:
// ω_d = √((ω₀S)² − β²). Reference: the unit sampled damped sine's line at that ω_d. Tolerance
// 1e-9 relative: the same line at every energy point.
TEST(CentroidPrediction, PlacesAShallowBubbleAtItsStrasbergFrequency) {
  const SynthesisSettings s = defaultSettings();
  const OscillatorConstants c = deepConstants(1e-3, s);
  BubbleTrackSet set;
  set.bubbles.push_back(steadyBubble(1e-3, 0.01, 2e-3, {1.0}));
  const double shifted = c.angularFrequency * freeSurfaceFrequencyRatio(1e-3, 2e-3);
  EXPECT_NEAR(freeSurfaceFrequencyRatio(1e-3, 2e-3), 1.15772, 1e-5);  // T3, h/R = 2
  const BandSpectrum line =
      DampedSineSpectrum(kSampleRate)
          .inBand(std::sqrt(shifted * shifted - c.decayRate * c.decayRate), c.decayRate, kAudible);
  const PredictedSpectrum p = predictedSpectra(set, s, kAudible).at(0);
  EXPECT_NEAR(p.centroid, line.centroid, 1e-9 * line.centroid);
  EXPECT_NEAR(p.bandEnergy, c.amplitude * c.amplitude * line.energy, 2e-9 * p.bandEnergy);
}

// Claim: each listener's channel is weighted by its own transfer²: two bubbles (1 and 2 mm), the
// first heard only on the left, the second only on the right, with transfer 0.5 and 0.25, give the
// left channel the first bubble's centroid and the right the second's, at energies scaled by
// 0.25 and 0.0625. Reference: the one-bubble predictions. Tolerance 1e-9 relative: the same sums.
TEST(CentroidPrediction, WeightsEachChannelByItsTransferSquared) {
  const SynthesisSettings s = defaultSettings();
  BubbleTrackSet both, small, large;
  both.listeners = {"left", "right"};
  both.bubbles = {steadyBubble(1e-3, 0.0, 1.0, {0.5, 0.0}),
                  steadyBubble(2e-3, 0.05, 1.0, {0.0, 0.25})};
  small.bubbles = {steadyBubble(1e-3, 0.0, 1.0, {1.0})};
  large.bubbles = {steadyBubble(2e-3, 0.05, 1.0, {1.0})};
  const std::vector<PredictedSpectrum> p = predictedSpectra(both, s, kAudible);
  const PredictedSpectrum a = predictedSpectra(small, s, kAudible)[0],
                          b = predictedSpectra(large, s, kAudible)[0];
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[0].centroid, a.centroid, 1e-9 * a.centroid);
  EXPECT_NEAR(p[1].centroid, b.centroid, 1e-9 * b.centroid);
  EXPECT_NEAR(p[0].bandEnergy, 0.25 * a.bandEnergy, 1e-9 * a.bandEnergy);
  EXPECT_NEAR(p[1].bandEnergy, 0.0625 * b.bandEnergy, 1e-9 * b.bandEnergy);
}

// Claim: what the synthesizer leaves out, the prediction leaves out: a bubble above Nyquist
// (R = 0.1 mm, 33 kHz at 48 kHz), one born after the clip's end, and the part of a decay cut by
// the clip's end: a 2 mm bubble (β ≈ 167/s) born 5 ms before the end keeps 1 − e^{−2β·5 ms} ≈ 81 %
// of the energy it has in an endless clip. Reference: that factor times the endless clip's
// prediction of the bubble alone. Tolerance 1e-9 relative: the same sums, scaled.
TEST(CentroidPrediction, LeavesOutWhatTheSynthesizerLeavesOut) {
  SynthesisSettings s = defaultSettings();
  BubbleTrackSet alone;
  alone.bubbles = {{2e-3, 0.095, std::nullopt, {}, {}}};
  const PredictedSpectrum endless = predictedSpectra(alone, s, kAudible).at(0);
  s.duration = 0.1;
  BubbleTrackSet set;
  set.bubbles = {{0.1e-3, 0.0, std::nullopt, {}, {}},
                 {1e-3, 0.2, std::nullopt, {}, {}},
                 {2e-3, 0.095, std::nullopt, {}, {}}};
  const PredictedSpectrum p = predictedSpectra(set, s, kAudible).at(0);
  EXPECT_EQ(p.bubbles, 1);
  const double kept = -std::expm1(-2.0 * deepConstants(2e-3, s).decayRate * 0.005);
  EXPECT_NEAR(p.bandEnergy, kept * endless.bandEnergy, 1e-9 * endless.bandEnergy);
  EXPECT_NEAR(p.centroid, endless.centroid, 1e-9 * endless.centroid);
}

}  // namespace
}  // namespace fluidsound::acoustics
