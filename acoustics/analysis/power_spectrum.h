// acoustics/analysis/power_spectrum.h — the power spectrum of a rendered signal and of its envelope (Welch
// averages of Hann-windowed segments), for the spectral checks of spectrum_statistics.h and the
// end-to-end tests (docs/synthesis.md, "What the spectrum shows").
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace fluidsound::acoustics {

/// A one-sided power spectral density on bins k·binWidth, k = 0 … N/2.
struct PowerSpectrum {
  double binWidth = 0.0;  ///< Δf = sampleRate / N [Hz]
  std::vector<double>
      power;  ///< density per bin [unit²/Hz]; Σ_k power[k]·Δf = mean power of the record
  /// Centre frequency of bin k [Hz].
  double frequency(std::size_t k) const { return static_cast<double>(k) * binWidth; }
};

/// @brief Welch's averaged periodogram (Welch 1967) of the whole record, with every sample weighted
///        equally: periodic Hann segments of N samples at a hop of N/4, the record zero-padded by
///        N − N/4 samples at both ends. Σ_m w²(n − mN/4) = 3/2 for every n (the Hann window's
///        square is constant-overlap-add at a quarter hop), so each sample enters the average with
///        the same weight and, by Parseval, Σ_k power[k]·Δf = (1/L) Σ_n x[n]² exactly (L samples):
///        a non-stationary signal (a pour that starts and stops) gives the spectrum of its whole
///        energy, not of the middle of the record.
/// @param signal          L ≥ 1 samples (any unit)
/// @param sampleRate      [Hz], > 0
/// @param segmentSamples  N, a multiple of 4, ≥ 16: bin width fs/N; the Hann main lobe is ±2 bins
/// @throws std::invalid_argument for an empty signal, non-finite samples or bad parameters
PowerSpectrum welchPowerSpectrum(std::span<const float> signal, double sampleRate,
                                 std::size_t segmentSamples);

/// @brief The power spectrum of the signal's envelope: welchPowerSpectrum of the instantaneous
///        power e[n] = x[n]² minus its record mean (the mean would only leak DC into the lowest
///        bins). A modulation of the loudness at a rate F — bubbles born in bursts every 1/F
///        seconds, a gain stepping at F — is a line at F and its harmonics here, whatever the
///        carrier's frequencies. x² needs no smoothing for this: a low-pass filter would scale the
///        low-frequency bins, not the ratio of a line to its neighbours (spectrum_statistics.h);
///        the 2f terms of x² lie at twice the bubble frequencies, far above the envelope rates.
/// @throws std::invalid_argument as welchPowerSpectrum
PowerSpectrum envelopePowerSpectrum(std::span<const float> signal, double sampleRate,
                                    std::size_t segmentSamples);

}  // namespace fluidsound::acoustics
