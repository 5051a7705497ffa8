// Tests of acoustics/analysis/power_spectrum.h: Welch spectra keep the record's energy (Parseval), weight
// every sample equally, and put an amplitude modulation's rate into the envelope spectrum.
#include "acoustics/analysis/power_spectrum.h"

#include <gtest/gtest.h>

#include "support/test_signals.h"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace fluidsound::acoustics {
namespace {

constexpr double kSampleRate = 48000.0;
constexpr std::size_t kSegment = 4096;

double meanSquare(const std::vector<float>& x) {
  double sum = 0.0;
  for (float v : x) sum += static_cast<double>(v) * v;
  return sum / static_cast<double>(x.size());
}

double integratedPower(const PowerSpectrum& s) {
  double sum = 0.0;
  for (double p : s.power) sum += p * s.binWidth;
  return sum;
}

using test::gaussianNoise;

// Claim: Σ_k P_k Δf equals the record's mean power (1/L) Σ x² — Parseval's theorem with the
// quarter-hop Hann overlap, whose squared windows sum to 3/2 at every sample (power_spectrum.h).
// Reference: the mean square computed directly. Tolerance 1e-9 relative: double rounding over
// ~10⁵ terms (the samples are float, the arithmetic double); any missing edge weight or wrong
// scale would be a fraction of a segment's share, ≥ 1e-2 here. A record length that is not a
// multiple of the hop checks the zero-padded ends.
TEST(PowerSpectrum, IntegratesToTheMeanPowerOfTheRecord) {
  const std::vector<float> x = gaussianNoise(48000 + 123, 7);
  const PowerSpectrum s = welchPowerSpectrum(x, kSampleRate, kSegment);
  EXPECT_EQ(s.power.size(), kSegment / 2 + 1);
  EXPECT_DOUBLE_EQ(s.binWidth, kSampleRate / kSegment);
  EXPECT_NEAR(integratedPower(s), meanSquare(x), 1e-9 * meanSquare(x));
}

// Claim: every sample counts the same, wherever it sits in the record: a 10 ms burst at the very
// start, in the middle or at the very end gives the same integrated power. Reference: the
// position-independent Σ x²/L. Tolerance 1e-9 relative, as above; a plain Welch average (no end
// padding) would weight the first and last samples by w² → 0, i.e. lose the edge bursts entirely.
TEST(PowerSpectrum, WeightsABurstAtTheEdgeLikeOneInTheMiddle) {
  const std::size_t length = 3 * kSegment, burst = 480;
  for (const std::size_t start : {std::size_t{0}, length / 2, length - burst}) {
    std::vector<float> x(length, 0.0f);
    for (std::size_t i = 0; i < burst; ++i)
      x[start + i] =
          static_cast<float>(std::sin(2.0 * std::numbers::pi * 1000.0 * i / kSampleRate));
    const PowerSpectrum s = welchPowerSpectrum(x, kSampleRate, kSegment);
    EXPECT_NEAR(integratedPower(s), meanSquare(x), 1e-9 * meanSquare(x))
        << "burst at sample " << start;
  }
}

// Claim: the envelope spectrum of a carrier modulated as (1 + m cos 2πFt) holds a line at F of
// power 2m²σ⁴ (x² = n²(1 + 2m cos + m² cos²), E n² = σ²), on a background of the carrier's own
// power fluctuation, white with one-sided density 4σ⁴/fs for Gaussian white noise (var n² = 2σ⁴).
// Reference: the line's power summed over its Hann main lobe (±2 bins) against 2m²σ⁴, m = 0.3,
// σ = 1. Tolerance 10 %: the background inside the 5 bins adds 5Δf·4σ⁴/fs = 20σ⁴/N (1.4 % of
// the line here), and the Welch estimate of the line bins scatters by the background's relative
// fluctuation (~1/√(dof), dof ≈ 2·1.9·L/N ≈ 220 for 10 s) scaled by its share — a few per cent at most.
TEST(PowerSpectrum, EnvelopeSpectrumHoldsTheModulationLine) {
  constexpr double kModulation = 0.3, kRate = 30.0;
  std::vector<float> x = gaussianNoise(2 * 48000 * 5, 11);
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] *= static_cast<float>(
        1.0 + kModulation * std::cos(2.0 * std::numbers::pi * kRate * i / kSampleRate));
  const PowerSpectrum s = envelopePowerSpectrum(x, kSampleRate, 8192);
  const auto centre = static_cast<std::ptrdiff_t>(std::lround(kRate / s.binWidth));
  double line = 0.0;
  for (std::ptrdiff_t k = centre - 2; k <= centre + 2; ++k)
    line += s.power[static_cast<std::size_t>(k)] * s.binWidth;
  const double expected = 2.0 * kModulation * kModulation;
  EXPECT_NEAR(line, expected, 0.1 * expected);
}

// Bad input is refused with the reason: no samples, NaN, a segment that is not a multiple of 4.
TEST(PowerSpectrum, RefusesBadInput) {
  const std::vector<float> empty, nan = {0.0f, std::nanf("")}, ok(100, 1.0f);
  EXPECT_THROW(welchPowerSpectrum(empty, kSampleRate, 64), std::invalid_argument);
  EXPECT_THROW(welchPowerSpectrum(nan, kSampleRate, 64), std::invalid_argument);
  EXPECT_THROW(welchPowerSpectrum(ok, kSampleRate, 66), std::invalid_argument);
  EXPECT_THROW(welchPowerSpectrum(ok, kSampleRate, 8), std::invalid_argument);
  EXPECT_THROW(welchPowerSpectrum(ok, 0.0, 64), std::invalid_argument);
  EXPECT_THROW(envelopePowerSpectrum(nan, kSampleRate, 64), std::invalid_argument);
}

}  // namespace
}  // namespace fluidsound::acoustics
