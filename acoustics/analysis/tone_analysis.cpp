// acoustics/analysis/tone_analysis.cpp — measuring the frequency and decay rate of a rendered bubble tone
// (docs/physics.md §8 and table T8): FFT peak, matrix pencil (Hua & Sarkar 1990), robust Hilbert
// envelope fit and zero-crossing instantaneous frequency. All arithmetic is in double; the float
// samples are only the storage format of a rendered WAV.
#include "acoustics/analysis/tone_analysis.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>
#include <unsupported/Eigen/FFT>

namespace fluidsound::acoustics {
namespace {

/// Fewest samples any estimator accepts: the matrix pencil needs L = N/3 ≥ 5 lags for its two
/// roots to be over-determined, and shorter records carry under a cycle of any audible tone.
constexpr std::size_t kMinimumSamples = 16;

/// §8 item 1: zero-pad to the next power of two ≥ 8N, so that the Hann main lobe spans ±16 bins
/// and the three points of the log-parabola sit near its top (interpolation bias ≪ 0.002 %, T8);
/// a power-of-two length is also the FFT's fastest.
constexpr std::size_t kPeakZeroPadFactor = 8;

/// §8 item 2: the pencil parameter L = N/3, the lower end of the range of least noise sensitivity
/// (N/3 ≤ L ≤ N/2, Sarkar & Pereira 1995); the lower end keeps the SVD smallest.
constexpr std::size_t kPencilDivisor = 3;

/// One real damped sinusoid is a conjugate pair of poles: signal-subspace rank M = 2.
constexpr Eigen::Index kModelOrder = 2;

/// Truncated SVD by subspace iteration (Halko, Martinsson & Tropp 2011, Alg. 4.4 + 5.1): a full
/// SVD of the (2N/3) × (N/3) Hankel matrix costs ~0.35 s at N = 2048, yet only M = 2 right singular
/// vectors are used. With k = M + 6 probe vectors and q = 2 power iterations the error of the
/// M Ritz vectors scales as (σ_{k+1}/σ_M)^(2q+1): σ_{k+1} is the noise floor (≤ 5·10⁻⁵ σ_M for
/// 16-bit T2a tones), so the result equals the full SVD's to rounding (checked against BDCSVD on
/// T2a tones, float32 and 16-bit: f and β agree to 10⁻¹²), at ~1/30 of the cost. q = 2 rather
/// than 1 keeps that equality (≤ 10⁻⁵) for a render as noisy as σ_{k+1} = 0.1 σ_M.
constexpr Eigen::Index kSubspaceOversampling = 6;
constexpr int kPowerIterations = 2;
/// Fixed seed of the probe vectors: results are bit-identical from run to run.
constexpr std::uint32_t kProbeSeed = 20240601u;

/// §8 item 3: fit guards of 3 cycles after the envelope peak (onset transient of the analytic
/// signal) and before the fit-range threshold (where the onset's Hilbert tail, decaying as 1/t,
/// is largest relative to the envelope).
constexpr double kGuardCycles = 3.0;
/// Fewest envelope samples in the log-linear fit: below this a slope is not a measurement.
constexpr std::size_t kMinimumFitSamples = 8;

void requireValidInput(std::span<const float> signal, double sampleRate, const char* function) {
  if (signal.size() < kMinimumSamples) {
    throw std::invalid_argument(std::string(function) + ": expected at least " +
                                std::to_string(kMinimumSamples) + " samples, found " +
                                std::to_string(signal.size()));
  }
  if (!(sampleRate > 0.0) || !std::isfinite(sampleRate)) {
    throw std::invalid_argument(std::string(function) + ": expected a sample rate > 0 Hz, found " +
                                std::to_string(sampleRate));
  }
  // A NaN would poison every estimate, and silence has no tone to measure (ln 0 in all three).
  bool silent = true;
  for (std::size_t i = 0; i < signal.size(); ++i) {
    if (!std::isfinite(signal[i])) {
      throw std::invalid_argument(std::string(function) + ": expected finite samples, found " +
                                  std::to_string(signal[i]) + " at sample " + std::to_string(i));
    }
    silent = silent && signal[i] == 0.0f;
  }
  if (silent) {
    throw std::invalid_argument(std::string(function) + ": expected a tone, found only zeros");
  }
}

std::size_t nextPowerOfTwo(std::size_t n) {
  std::size_t p = 1;
  while (p < n) p *= 2;
  return p;
}

/// Orthonormal basis (thin Q of a Householder QR) of the columns of `a`.
Eigen::MatrixXd orthonormalColumns(const Eigen::MatrixXd& a) {
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
  return qr.householderQ() * Eigen::MatrixXd::Identity(a.rows(), a.cols());
}

/// The `count` leading right singular vectors of `h` ((cols) × count), by randomized subspace
/// iteration and a Rayleigh–Ritz step: an exact (Jacobi) SVD of the small matrix QᵀH, whose right
/// singular vectors are those of H restricted to the captured subspace.
Eigen::MatrixXd leadingRightSingularVectors(const Eigen::MatrixXd& h, Eigen::Index count) {
  const Eigen::Index probes = std::min<Eigen::Index>(count + kSubspaceOversampling,
                                                     std::min(h.rows(), h.cols()));
  // Uniform probes in [−1, 1) from std::mt19937, whose output sequence the standard fixes (the
  // standard distributions' algorithms are implementation-defined).
  std::mt19937 generator(kProbeSeed);
  constexpr double kTwoToThe32 = 4294967296.0;
  Eigen::MatrixXd omega(h.cols(), probes);
  for (Eigen::Index j = 0; j < probes; ++j) {
    for (Eigen::Index i = 0; i < h.cols(); ++i) {
      omega(i, j) = 2.0 * static_cast<double>(generator()) / kTwoToThe32 - 1.0;
    }
  }
  Eigen::MatrixXd q = orthonormalColumns(h * omega);
  for (int iteration = 0; iteration < kPowerIterations; ++iteration) {
    // Re-orthonormalise after each product so that σ₁/σ_k does not swamp the smaller directions.
    const Eigen::MatrixXd w = orthonormalColumns(h.transpose() * q);
    q = orthonormalColumns(h * w);
  }
  const Eigen::MatrixXd b = q.transpose() * h;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(b, Eigen::ComputeThinV);
  return svd.matrixV().leftCols(count);
}

}  // namespace

double fftPeakFrequency(std::span<const float> signal, double sampleRate) {
  requireValidInput(signal, sampleRate, "fftPeakFrequency");
  const std::size_t n = signal.size();
  const std::size_t nfft = nextPowerOfTwo(kPeakZeroPadFactor * n);

  // Hann window (symmetric): sidelobes fall as 1/k³, so the leakage of the negative-frequency image
  // and of the abrupt onset into the peak's neighbourhood stays far below the 0.002 % budget (T8).
  std::vector<double> windowed(nfft, 0.0);
  const double step = 2.0 * std::numbers::pi / static_cast<double>(n - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double hann = 0.5 - 0.5 * std::cos(step * static_cast<double>(i));
    windowed[i] = hann * static_cast<double>(signal[i]);
  }
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);  // real input: bins 0 … nfft/2 suffice
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, windowed);

  // Strongest bin, skipping DC (bin 0) and stopping one short of Nyquist so that both neighbours
  // of the peak exist.
  std::size_t peak = 1;
  double peakMagnitude = -1.0;
  for (std::size_t k = 1; k + 1 < spectrum.size(); ++k) {
    const double magnitude = std::abs(spectrum[k]);
    if (magnitude > peakMagnitude) {
      peakMagnitude = magnitude;
      peak = k;
    }
  }
  // Parabola through the log magnitudes (§8 item 1): exact for a Gaussian lobe, and a Hann lobe
  // is close to Gaussian near its top; ln|X| is symmetric about f for a damped sinusoid (the
  // magnitude of the transform of a real envelope is even), so the vertex is unbiased up to
  // negative-frequency leakage.
  const double a = std::log(std::abs(spectrum[peak - 1]));
  const double b = std::log(peakMagnitude);
  const double c = std::log(std::abs(spectrum[peak + 1]));
  const double curvature = a - 2.0 * b + c;
  const double offset = curvature < 0.0 ? 0.5 * (a - c) / curvature : 0.0;
  return (static_cast<double>(peak) + offset) * sampleRate / static_cast<double>(nfft);
}

DampedToneEstimate matrixPencilEstimate(std::span<const float> signal, double sampleRate,
                                        std::size_t maxSamples) {
  requireValidInput(signal, sampleRate, "matrixPencilEstimate");
  const std::size_t n = std::min(signal.size(), maxSamples);
  if (n < kMinimumSamples) {
    throw std::invalid_argument("matrixPencilEstimate: expected at least " +
                                std::to_string(kMinimumSamples) + " samples, found maxSamples = " +
                                std::to_string(maxSamples));
  }
  // All of the first N samples are used, with no cut at −60 dB (§8 allows either): the SVD weights
  // each window by its energy, so samples far down the decay barely move the subspace, and T8's
  // errors are met without the cut.
  if (std::all_of(signal.begin(), signal.begin() + static_cast<std::ptrdiff_t>(n),
                  [](float x) { return x == 0.0f; })) {
    throw std::invalid_argument("matrixPencilEstimate: expected a tone in the first " +
                                std::to_string(n) + " samples, found only zeros");
  }
  // Hankel matrix of the windows x[i … i+L], i = 0 … N−L−1 (Hua & Sarkar 1990, with SVD noise
  // filtering). For one damped tone its row space is spanned by (1, z, …, z^L) and its conjugate.
  const std::size_t pencil = n / kPencilDivisor;
  const std::size_t rows = n - pencil;
  Eigen::MatrixXd hankel(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(pencil + 1));
  for (std::size_t j = 0; j <= pencil; ++j) {
    for (std::size_t i = 0; i < rows; ++i) {
      hankel(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          static_cast<double>(signal[i + j]);
    }
  }
  // Rank-M signal subspace V ((L+1) × M); V₁ = V without its last row, V₂ without its first.
  // The shift invariance V₂ = V₁·F makes the eigenvalues of F = pinv(V₁)·V₂ the poles z.
  const Eigen::MatrixXd v = leadingRightSingularVectors(hankel, kModelOrder);
  const Eigen::Index lags = v.rows() - 1;
  const Eigen::MatrixXd v1 = v.topRows(lags);
  const Eigen::MatrixXd v2 = v.bottomRows(lags);
  // The least-squares (minimum-norm) solution of V₁F = V₂ is pinv(V₁)·V₂.
  const Eigen::MatrixXd f =
      v1.jacobiSvd(Eigen::ComputeThinU | Eigen::ComputeThinV).solve(v2);
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(f, /*computeEigenvectors=*/false);

  // The root with positive angle. A real tone gives a conjugate pair; if noise leaves two real
  // roots, the one of larger angle is still the best single answer (f = 0 or fs/2 flags it).
  std::complex<double> pole = eigen.eigenvalues()(0);
  for (Eigen::Index i = 1; i < eigen.eigenvalues().size(); ++i) {
    if (std::arg(eigen.eigenvalues()(i)) > std::arg(pole)) pole = eigen.eigenvalues()(i);
  }
  DampedToneEstimate estimate;
  estimate.frequency = std::abs(std::arg(pole)) * sampleRate / (2.0 * std::numbers::pi);
  estimate.decayRate = -std::log(std::abs(pole)) * sampleRate;
  return estimate;
}

double hilbertDecayRate(std::span<const float> signal, double sampleRate, double frequency,
                        double fitRangeDecibels) {
  requireValidInput(signal, sampleRate, "hilbertDecayRate");
  if (!(frequency > 0.0) || !std::isfinite(frequency)) {
    throw std::invalid_argument("hilbertDecayRate: expected a tone frequency > 0 Hz, found " +
                                std::to_string(frequency));
  }
  if (!(fitRangeDecibels > 0.0)) {
    throw std::invalid_argument("hilbertDecayRate: expected fitRangeDecibels > 0 dB, found " +
                                std::to_string(fitRangeDecibels));
  }
  // Accuracy (T8 grid, and all onset phases in tests/acoustics/analysis/tone_analysis_test.cpp): ≤ 0.1 % for
  // the T2a bubbles up to 6.6 kHz; for the 0.25 mm bubble (13 kHz, β = 2552 /s) the fit window is
  // only ~40 samples and the Hilbert transform's tail from the abrupt onset (∝ 1/t, not removed by
  // padding) is a ripple of ~10 % on the envelope at −30 dB: 0.24 % for sin/cos onsets (T8) but
  // up to 0.4 % for other onset phases — inside the 1 % validation budget; prefer the matrix pencil
  // there.
  const std::size_t n = signal.size();
  // N zeros before and at least N after (§8 item 3): the FFT's circular Hilbert transform would
  // otherwise wrap the onset transient onto the end of the record, where the envelope is smallest
  // (the "naive Hilbert" pitfall of §8: 3.6 /s instead of 260 /s). The length is rounded up to a
  // power of two for the FFT; the extra zeros only lengthen the trailing pad.
  // Padding and the contiguous run below each defend against that pitfall; the run is the one
  // that matters for accuracy (padding with a fit over every sample above −40 dB still gives
  // −0.6 % on §8's pitfall tones; the contiguous run without padding stays within 0.25 %).
  const std::size_t nfft = nextPowerOfTwo(3 * n);
  std::vector<std::complex<double>> padded(nfft, 0.0);
  for (std::size_t i = 0; i < n; ++i) padded[n + i] = static_cast<double>(signal[i]);

  // Analytic signal (Marple 1999): keep DC and Nyquist, double positive, zero negative frequencies.
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, padded);
  for (std::size_t k = 1; k < nfft / 2; ++k) spectrum[k] *= 2.0;
  for (std::size_t k = nfft / 2 + 1; k < nfft; ++k) spectrum[k] = 0.0;
  std::vector<std::complex<double>> analytic;
  fft.inv(analytic, spectrum);  // scaled by 1/nfft (Eigen's default)

  std::vector<double> envelope(n);
  for (std::size_t i = 0; i < n; ++i) envelope[i] = std::abs(analytic[n + i]);
  const auto peakIt = std::max_element(envelope.begin(), envelope.end());
  const std::size_t peak = static_cast<std::size_t>(peakIt - envelope.begin());
  const double threshold = *peakIt * std::pow(10.0, -fitRangeDecibels / 20.0);

  // The contiguous run from peak + 3 cycles to 3 cycles before the first sample below threshold
  // (or before the end of the record if the envelope never gets there).
  std::size_t firstBelow = peak;
  while (firstBelow < n && envelope[firstBelow] >= threshold) ++firstBelow;
  // Guards rounded to the nearest sample: at 13 kHz / 44.1 kHz (3.35 samples per cycle) one sample
  // more or less moves β by ~0.2 %; nearest rounding reproduces T8's 0.240 % worst case exactly,
  // rounding up gives 0.46 %.
  const auto guard = static_cast<std::size_t>(std::lround(kGuardCycles * sampleRate / frequency));
  const std::size_t begin = peak + guard;
  const std::size_t end = firstBelow > guard ? firstBelow - guard : 0;
  if (end <= begin || end - begin < kMinimumFitSamples) {
    throw std::invalid_argument(
        "hilbertDecayRate: expected at least " + std::to_string(kMinimumFitSamples) +
        " envelope samples between the 3-cycle guards within " + std::to_string(fitRangeDecibels) +
        " dB of the peak, found " + std::to_string(end > begin ? end - begin : 0) +
        " (tone too short, too strongly damped, or frequency wrong)");
  }
  // Ordinary least squares of ln(envelope) on the sample index, about the means for accuracy.
  const double count = static_cast<double>(end - begin);
  const double meanIndex = 0.5 * static_cast<double>(begin + end - 1);
  double meanLog = 0.0;
  for (std::size_t i = begin; i < end; ++i) meanLog += std::log(envelope[i]);
  meanLog /= count;
  double covariance = 0.0;
  double variance = 0.0;
  for (std::size_t i = begin; i < end; ++i) {
    const double di = static_cast<double>(i) - meanIndex;
    covariance += di * (std::log(envelope[i]) - meanLog);
    variance += di * di;
  }
  const double slopePerSample = covariance / variance;
  return -slopePerSample * sampleRate;
}

std::vector<FrequencyAtTime> zeroCrossingFrequencies(std::span<const float> signal,
                                                     double sampleRate) {
  if (!(sampleRate > 0.0) || !std::isfinite(sampleRate)) {
    throw std::invalid_argument("zeroCrossingFrequencies: expected a sample rate > 0 Hz, found " +
                                std::to_string(sampleRate));
  }
  // Upward crossings x[i] < 0 ≤ x[i+1], at the zero of the chord between the two samples (in
  // samples from the start). At a zero crossing sin'' = 0, so the chord misplaces a crossing by at
  // most θ²/(36√3) samples, θ = 2πf/fs, and a period by twice that: a relative error per period of
  // up to ≈ θ³/(36√3π) — 0.04 % at 3.3 kHz / 48 kHz, 0.2 % at f ≈ fs/8.6 (5.1 kHz at 44.1 kHz),
  // 3 % at 13 kHz. Decay and sweep add a smaller second-order term (§8 item 4). A noisy signal
  // can cross more than once per period: no hysteresis is applied, the input is a clean render.
  std::vector<double> crossings;
  for (std::size_t i = 0; i + 1 < signal.size(); ++i) {
    const double x0 = signal[i];
    const double x1 = signal[i + 1];
    if (x0 < 0.0 && x1 >= 0.0) crossings.push_back(static_cast<double>(i) + x0 / (x0 - x1));
  }
  std::vector<FrequencyAtTime> result;
  if (crossings.size() < 2) return result;
  result.reserve(crossings.size() - 1);
  for (std::size_t k = 0; k + 1 < crossings.size(); ++k) {
    const double periodSamples = crossings[k + 1] - crossings[k];
    result.push_back({0.5 * (crossings[k] + crossings[k + 1]) / sampleRate,
                      sampleRate / periodSamples});
  }
  return result;
}

}  // namespace fluidsound::acoustics
