// Tests of acoustics/analysis/spectrum_statistics.h: the spectral centroid of tones with known powers, the
// prominence of an envelope line from amplitude modulation, and the frame-rate line that bubbles
// born only at frame instants would leave (issue 6: "no line at the frame rate or its harmonics").
#include "acoustics/analysis/spectrum_statistics.h"

#include <gtest/gtest.h>

#include "support/test_signals.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "acoustics/analysis/power_spectrum.h"
#include "acoustics/synthesis/synthesizer.h"
#include "support/frame_rate_lines.h"

namespace fluidsound::acoustics {
namespace {

constexpr double kSampleRate = 48000.0;
constexpr std::size_t kSegment = test::kFrameLineSegment;  // 2.93 Hz bins
constexpr double kFrameRate = 30.0;                        // frames/s [Hz]

std::vector<float> tones(const std::vector<std::pair<double, double>>& frequencyAmplitude,
                         double seconds) {
  std::vector<float> x(static_cast<std::size_t>(seconds * kSampleRate));
  for (std::size_t i = 0; i < x.size(); ++i) {
    double v = 0.0;
    for (const auto& [f, a] : frequencyAmplitude)
      v += a * std::sin(2.0 * std::numbers::pi * f * i / kSampleRate + 0.3);
    x[i] = static_cast<float>(v);
  }
  return x;
}

using test::gaussianNoise;

// Claim: a pure tone's centroid is its frequency. Reference: f = 1234.5 Hz (between bins). The
// sampled first moment of a window's power response |W|² is exact at any offset (its transform,
// the window's autocorrelation, vanishes at lag N, so Poisson summation leaves no alias term) and
// |W|² is symmetric for a real window, even for the segments the record's ends truncate; what is
// left is the negative-frequency image's tail and the band edges. Tolerance 1e-4 relative, a
// generous bound on those (the image's tail beyond ±1 kHz is below −100 dB of the line).
TEST(SpectralCentroid, OfAPureToneIsItsFrequency) {
  const std::vector<float> x = tones({{1234.5, 1.0}}, 1.0);
  const double c = spectralCentroid(welchPowerSpectrum(x, kSampleRate, 4096), {234.5, 2234.5});
  EXPECT_NEAR(c, 1234.5, 1e-4 * 1234.5);
}

// Claim: two tones of amplitudes a₁, a₂ have the power-weighted mean frequency as centroid,
// (a₁²f₁ + a₂²f₂)/(a₁² + a₂²). Reference: 1 kHz at amplitude 1 and 3 kHz at amplitude 0.5 →
// (1000 + 0.25·3000)/1.25 = 1400 Hz. Tolerance 1e-4 relative, as for one tone.
TEST(SpectralCentroid, OfTwoTonesIsThePowerWeightedMean) {
  const std::vector<float> x = tones({{1000.0, 1.0}, {3000.0, 0.5}}, 1.0);
  const double c = spectralCentroid(welchPowerSpectrum(x, kSampleRate, 4096), {20.0, 20000.0});
  EXPECT_NEAR(c, 1400.0, 1e-4 * 1400.0);
}

TEST(SpectralCentroid, RefusesABandWithoutPower) {
  const PowerSpectrum s = welchPowerSpectrum(std::vector<float>(1000, 0.0f), kSampleRate, 256);
  EXPECT_THROW(spectralCentroid(s, {20.0, 20000.0}), std::invalid_argument);
  EXPECT_THROW(spectralCentroid(s, {30000.0, 40000.0}), std::invalid_argument);
}

// Claim: noise modulated in loudness at 30 Hz, (1 + m cos 2π·30t), shows a line at 30 Hz in its
// envelope spectrum; the same noise unmodulated shows none at 30 Hz or its harmonics.
// Reference (power_spectrum_test.cpp): a line of power 2m²σ⁴ over a white background of density
// 4σ⁴/fs; at its peak bin a Hann-windowed line has density power/(1.5Δf) (equivalent noise
// bandwidth 1.5 bins, Harris 1978), so the prominence is 10 log₁₀(m²N/3) = 17.4 dB for m = 0.1
// (a −20 dB modulation depth, near the threshold of hearing for AM of noise at 30 Hz, Viemeister
// 1979), N = 16384. Tolerance ±3 dB: scalloping (30 Hz is 0.24 bin off a bin centre: −0.3 dB) and
// the scatter of the Welch estimate (dof ≈ 2·1.9·L/N ≈ 22 for 2 s: a bin within ±2 dB).
// Unmodulated: below 6 dB everywhere, a level the background's own fluctuations reach with
// probability < 10⁻⁴ per harmonic at that dof (χ²₂₂/22 > 4 × its median).
TEST(LineProminence, AmplitudeModulationAt30HzIsALineInTheEnvelopeSpectrum) {
  constexpr double kModulation = 0.1;
  std::vector<float> plain = gaussianNoise(2 * 48000, 3), modulated = plain;
  for (std::size_t i = 0; i < modulated.size(); ++i)
    modulated[i] *= static_cast<float>(
        1.0 + kModulation * std::cos(2.0 * std::numbers::pi * kFrameRate * i / kSampleRate));
  const double expected = 10.0 * std::log10(kModulation * kModulation * kSegment / 3.0);
  const LineProminence line =
      lineProminence(envelopePowerSpectrum(modulated, kSampleRate, kSegment), kFrameRate, 15.0);
  EXPECT_NEAR(line.prominenceDecibels, expected, 3.0);
  const std::vector<LineProminence> none =
      harmonicLineProminences(envelopePowerSpectrum(plain, kSampleRate, kSegment), kFrameRate, 10);
  ASSERT_EQ(none.size(), 10u);
  EXPECT_LT(test::largestProminence(none), 6.0) << test::describeLines(none);
}

TEST(LineProminence, RefusesANeighbourhoodNarrowerThanTheGuards) {
  const PowerSpectrum s = welchPowerSpectrum(gaussianNoise(20000, 1), kSampleRate, kSegment);
  EXPECT_THROW(lineProminence(s, 30.0, 5.0), std::invalid_argument);  // 5 Hz < 3 bins + 1
  EXPECT_NO_THROW(lineProminence(s, 30.0, 15.0));
}

// Claim: the mean of K line ratios has the background's scatter shrunk by averaging: on noise it
// is the mean of (largest of 3 bins)/(median of 6), about +1.8 dB, whatever the spread of one
// line. Reference: 10 log₁₀ of the mean of the linear ratios, computed by hand for 0, 10, 20 dB
// lines: mean(1, 10, 100) = 37 → 15.68 dB. Tolerance 1e-12 dB (arithmetic).
TEST(LineProminence, MeanIsTheMeanOfTheLinearRatios) {
  std::vector<LineProminence> lines(3);
  lines[0].prominenceDecibels = 0.0;
  lines[1].prominenceDecibels = 10.0;
  lines[2].prominenceDecibels = 20.0;
  EXPECT_NEAR(meanProminenceDecibels(lines), 10.0 * std::log10(37.0), 1e-12);
  EXPECT_THROW(meanProminenceDecibels({}), std::invalid_argument);
}

/// A stationary pour of deep bubbles (no track, transfer 1): Poisson births at 1000 per second over
/// 0.6 s (the end-to-end pour's density and length), radii log-uniform in 0.2 … 3 mm; with
/// `quantised`, every birth moved down to the frame instant before it, as a frame-stepped bubble
/// model would place it.
BubbleTrackSet poissonBubbles(bool quantised, std::uint32_t seed) {
  constexpr double kRate = 1000.0, kSeconds = 0.6;
  std::mt19937 generator(seed);
  std::exponential_distribution<double> gap(kRate);
  std::uniform_real_distribution<double> logRadius(std::log(0.2e-3), std::log(3e-3));
  BubbleTrackSet set;
  set.sampleRate = kSampleRate;
  set.duration = kSeconds;
  for (double t = gap(generator); t < kSeconds; t += gap(generator)) {
    BubbleTrack b;
    b.radius = std::exp(logRadius(generator));
    b.birth = quantised ? std::floor(t * kFrameRate) / kFrameRate : t;
    set.bubbles.push_back(b);
  }
  return set;
}

test::FrameRateLines renderedLines(const BubbleTrackSet& set) {
  SynthesisSettings settings;
  settings.sampleRate = kSampleRate;
  settings.duration = set.duration;
  return test::frameRateLines(synthesize(set, settings).channels.at(0), kSampleRate, kFrameRate);
}

// Claim: the frame-rate check (tests/support/frame_rate_lines.h) passes a pour with continuous
// births and fails the same pour with its births quantised to the frames. With births on the
// frame instants the mean instantaneous power E[x²(t)] repeats every 1/30 s — ~1 ms bursts of
// bubble energy 33 ms apart — so its Fourier series has a line at every multiple of 30 Hz up to
// ~β/π (hundreds of Hz); and as every bubble starts at phase 0, E[x(t)] repeats too, whose lines
// reach 30 … 300 Hz through the flat low tail of each bubble's spectrum. Continuous (Poisson)
// births leave both constant. Reference: the same pour (seed 5) both ways. Tolerance: the check's
// own limits, 12 dB for any line and 6 dB for the mean, whose margins over 200 pours are given
// in frame_rate_lines.h.
TEST(LineProminence, BirthsQuantisedToFramesFailTheFrameRateCheck) {
  const test::FrameRateLines continuous = renderedLines(poissonBubbles(false, 5));
  const test::FrameRateLines quantised = renderedLines(poissonBubbles(true, 5));
  for (const auto* lines : {&continuous.envelope, &continuous.spectrum}) {
    EXPECT_LT(test::largestProminence(*lines), test::kFrameLineLimitDecibels)
        << test::describeLines(*lines);
    EXPECT_LT(meanProminenceDecibels(*lines), test::kFrameCombLimitDecibels)
        << test::describeLines(*lines);
  }
  for (const auto* lines : {&quantised.envelope, &quantised.spectrum})
    EXPECT_GT(meanProminenceDecibels(*lines), test::kFrameCombLimitDecibels)
        << test::describeLines(*lines);
  std::cout << "[ measured ] continuous births: envelope "
            << test::describeLines(continuous.envelope)
            << "\n[ measured ] quantised births: envelope "
            << test::describeLines(quantised.envelope) << "\n";
}

}  // namespace
}  // namespace fluidsound::acoustics
