// Tests of acoustics/analysis/damped_sine_spectrum.h: the band energy and centroid of a sampled damped sine
// against the FFT of its samples.
#include "acoustics/analysis/damped_sine_spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "acoustics/bubble/bubble_oscillator.h"

namespace fluidsound::acoustics {
namespace {

constexpr double kSampleRate = 48000.0;

/// |X_k|² of e^{−βnΔt} sin(ω_d nΔt) from the DFT of 2¹⁹ samples (10.9 s): the tone has decayed
/// by > 5000 dB at the end for β ≥ 53/s, so the DFT samples its transform exactly, at bins
/// 0.092 Hz apart.
std::vector<double> samplePowers(double angularFrequency, double decayRate) {
  constexpr std::size_t kLength = std::size_t{1} << 19;
  std::vector<double> x(kLength);
  for (std::size_t n = 0; n < kLength; ++n) {
    const double t = static_cast<double>(n) / kSampleRate;
    x[n] = std::exp(-decayRate * t) * std::sin(angularFrequency * t);
  }
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  std::vector<std::complex<double>> bins;
  fft.fwd(bins, x);
  std::vector<double> power(bins.size());
  for (std::size_t k = 0; k < bins.size(); ++k) power[k] = std::norm(bins[k]);
  return power;
}

/// Band energy and centroid from those bins, the band widened to the edges of the bins' cells
/// (bin k stands for [k − ½, k + ½]·Δf: a midpoint rule with no partial cell at the ends); Parseval
/// gives Σx² = (1/M)Σ|X_k|² over all M bins, and the one-sided band holds twice its positive bins.
/// @return the result and, in `cells`, the band it is for
BandSpectrum inBandFromBins(const std::vector<double>& power, const FrequencyBand& band,
                            FrequencyBand& cells) {
  const double length = static_cast<double>(2 * (power.size() - 1));
  const double binWidth = kSampleRate / length;
  const auto first = static_cast<std::size_t>(std::lround(band.low / binWidth));
  const auto last = static_cast<std::size_t>(std::lround(band.high / binWidth));
  cells = {(static_cast<double>(first) - 0.5) * binWidth,
           (static_cast<double>(last) + 0.5) * binWidth};
  double sum = 0.0, moment = 0.0;
  for (std::size_t k = first; k <= last; ++k) {
    sum += power[k];
    moment += static_cast<double>(k) * binWidth * power[k];
  }
  return {2.0 * sum / length / kSampleRate, moment / sum};
}

// Claim: the band energy and centroid computed by the Gauss–Legendre sum over the closed-form
// transform equal those of the samples' own spectrum, for deep bubbles of R = 0.2, 0.5, 1, 5 mm
// (16.4, 6.6, 3.3, 0.66 kHz; β from 53 to 5700 /s) in 20 Hz … 20 kHz, and in the band 0.5 … 0.8 f
// on the line's low tail. Reference: the DFT of 2¹⁹ samples (samplePowers). Tolerance 10⁻⁴
// relative: the quadrature's ~10⁻⁵ (damped_sine_spectrum.h); the DFT's midpoint sum errs by
// ~(bin width / line width)² ≤ (0.09 Hz / 8.5 Hz)² ≈ 10⁻⁴ at worst (R = 5 mm) and far less
// elsewhere.
TEST(DampedSineSpectrum, EqualsTheSpectrumOfTheSamples) {
  const LiquidProperties liquid;
  const OscillatorModel model;
  const DampedSineSpectrum spectrum(kSampleRate);
  for (const double radius : {0.2e-3, 0.5e-3, 1e-3, 5e-3}) {
    const OscillatorConstants c = bubbleOscillator(radius, liquid.ambientPressure, liquid, model);
    const double wd =
        std::sqrt(c.angularFrequency * c.angularFrequency - c.decayRate * c.decayRate);
    const double f = wd / (2.0 * std::numbers::pi);
    const std::vector<double> power = samplePowers(wd, c.decayRate);
    for (const FrequencyBand band :
         {FrequencyBand{20.0, 20000.0}, FrequencyBand{0.5 * f, 0.8 * f}}) {
      FrequencyBand cells;
      const BandSpectrum expected = inBandFromBins(power, band, cells);
      const BandSpectrum got = spectrum.inBand(wd, c.decayRate, cells);
      EXPECT_NEAR(got.energy, expected.energy, 1e-4 * expected.energy)
          << "R = " << radius << " m, band from " << band.low;
      EXPECT_NEAR(got.centroid, expected.centroid, 1e-4 * expected.centroid)
          << "R = " << radius << " m, band from " << band.low;
    }
  }
}

// Claim: over the whole band 0 … fs/2 the energy is that of the unit damped sine,
// Σ_n e^{−2βnΔt} sin²(ω_d nΔt)·Δt = (Δt/2)[1/(1 − r²) − Re 1/(1 − r² e^{2iω_dΔt})], r = e^{−βΔt}
// (a geometric series). Reference: that closed form for R = 1 mm. Tolerance 10⁻⁵ relative, the
// quadrature's accuracy.
TEST(DampedSineSpectrum, HoldsTheWholeEnergyOverTheWholeBand) {
  const double wd = 2.0 * std::numbers::pi * 3288.3, beta = 407.85, dt = 1.0 / kSampleRate;
  const double r2 = std::exp(-2.0 * beta * dt);
  const double energy =
      0.5 * dt * (1.0 / (1.0 - r2) - std::real(1.0 / (1.0 - r2 * std::polar(1.0, 2.0 * wd * dt))));
  const BandSpectrum got =
      DampedSineSpectrum(kSampleRate).inBand(wd, beta, {0.0, kSampleRate / 2.0});
  EXPECT_NEAR(got.energy, energy, 1e-5 * energy);
  // The continuous tone's energy ω_d²/(4βω₀²) differs from the sampled one by O((βΔt)²) only.
  EXPECT_NEAR(got.energy, wd * wd / (4.0 * beta * (wd * wd + beta * beta)), 1e-3 * energy);
}

}  // namespace
}  // namespace fluidsound::acoustics
