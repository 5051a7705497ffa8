// acoustics/analysis/power_spectrum.cpp — Welch power spectra (see power_spectrum.h). Arithmetic in double;
// the FFT is Eigen's (as tone_analysis.cpp and the spectrogram).
#include "acoustics/analysis/power_spectrum.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unsupported/Eigen/FFT>

namespace fluidsound::acoustics {
namespace {

/// Segments overlap by 3/4: the hop at which the periodic Hann window's square sums to a constant
/// (sin⁴ = 3/8 − ½cos 2x + ⅛cos 4x; four shifts by π/4 cancel both cosines), Σ_m w² = 3/2.
constexpr std::size_t kHopsPerSegment = 4;
constexpr double kHannSquareOverlapSum = 1.5;
/// Shortest segment: a Hann window shorter than this has no usable main lobe.
constexpr std::size_t kMinimumSegmentSamples = 16;

void requireValidInput(std::span<const double> signal, double sampleRate,
                       std::size_t segmentSamples) {
  if (signal.empty())
    throw std::invalid_argument("welchPowerSpectrum: expected samples, found none");
  if (!(sampleRate > 0.0) || !std::isfinite(sampleRate))
    throw std::invalid_argument("welchPowerSpectrum: expected a sample rate > 0 Hz, found " +
                                std::to_string(sampleRate));
  if (segmentSamples < kMinimumSegmentSamples || segmentSamples % kHopsPerSegment != 0)
    throw std::invalid_argument(
        "welchPowerSpectrum: expected a segment of ≥ 16 samples, a multiple of 4, found " +
        std::to_string(segmentSamples));
  for (std::size_t i = 0; i < signal.size(); ++i)
    if (!std::isfinite(signal[i]))
      throw std::invalid_argument("welchPowerSpectrum: expected finite samples, found " +
                                  std::to_string(signal[i]) + " at sample " + std::to_string(i));
}

PowerSpectrum welch(std::span<const double> signal, double sampleRate, std::size_t n) {
  requireValidInput(signal, sampleRate, n);
  const auto length = static_cast<std::ptrdiff_t>(signal.size());
  const auto segment = static_cast<std::ptrdiff_t>(n);
  const std::ptrdiff_t hop = segment / static_cast<std::ptrdiff_t>(kHopsPerSegment);

  // Periodic Hann w[j] = sin²(πj/N) (Harris 1978): the form whose square overlap-adds exactly.
  std::vector<double> window(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double s = std::sin(std::numbers::pi * static_cast<double>(j) / static_cast<double>(n));
    window[j] = s * s;
  }
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);  // real input: bins 0 … N/2
  std::vector<double> windowed(n);
  std::vector<std::complex<double>> bins;
  std::vector<double> sum(n / 2 + 1, 0.0);
  // Segments start at −(N − hop), −(N − 2hop), …, so that the first and last samples are covered
  // by as many windows (four) as every other sample.
  for (std::ptrdiff_t start = hop - segment; start < length; start += hop) {
    for (std::ptrdiff_t j = 0; j < segment; ++j) {
      const std::ptrdiff_t i = start + j;
      windowed[static_cast<std::size_t>(j)] =
          (i >= 0 && i < length)
              ? window[static_cast<std::size_t>(j)] * signal[static_cast<std::size_t>(i)]
              : 0.0;
    }
    fft.fwd(bins, windowed);
    for (std::size_t k = 0; k < sum.size(); ++k) sum[k] += std::norm(bins[k]);
  }
  // Parseval: Σ over all N bins of |X|² = N Σ_j (w x)², and Σ over segments of (w x)² = (3/2) Σ x².
  // A one-sided density doubles every bin but DC and Nyquist; dividing by Δf = fs/N makes
  // Σ_k P_k Δf the mean power (1/L) Σ x².
  PowerSpectrum spectrum;
  spectrum.binWidth = sampleRate / static_cast<double>(n);
  const double scale = 1.0 / (static_cast<double>(n) * kHannSquareOverlapSum *
                              static_cast<double>(length) * spectrum.binWidth);
  spectrum.power.resize(sum.size());
  for (std::size_t k = 0; k < sum.size(); ++k) {
    const double oneSided = (k == 0 || k == n / 2) ? 1.0 : 2.0;
    spectrum.power[k] = oneSided * scale * sum[k];
  }
  return spectrum;
}

}  // namespace

PowerSpectrum welchPowerSpectrum(std::span<const float> signal, double sampleRate,
                                 std::size_t segmentSamples) {
  const std::vector<double> x(signal.begin(), signal.end());
  return welch(x, sampleRate, segmentSamples);
}

PowerSpectrum envelopePowerSpectrum(std::span<const float> signal, double sampleRate,
                                    std::size_t segmentSamples) {
  std::vector<double> power(signal.size());
  double mean = 0.0;
  for (std::size_t i = 0; i < signal.size(); ++i) {
    const double x = signal[i];
    power[i] = x * x;
    mean += power[i];
  }
  if (!power.empty()) mean /= static_cast<double>(power.size());
  for (double& e : power) e -= mean;
  return welch(power, sampleRate, segmentSamples);
}

}  // namespace fluidsound::acoustics
