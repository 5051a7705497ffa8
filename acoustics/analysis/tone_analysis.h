// acoustics/analysis/tone_analysis.h — measuring the frequency and decay rate of a rendered bubble tone,
// for tests and `fluidsound validate` (docs/physics.md §8: FFT peak, matrix pencil, robust Hilbert
// envelope fit, zero-crossing instantaneous frequency).
#pragma once

#include <span>
#include <vector>

namespace fluidsound::acoustics {

/// @brief Frequency [Hz] of the strongest spectral peak: Hann window, zero-padded to the next power
///        of two ≥ 8N, parabola through the log magnitudes at the peak bin and its neighbours.
/// @param signal      samples (any unit), N ≥ 16
/// @param sampleRate  [Hz]
double fftPeakFrequency(std::span<const float> signal, double sampleRate);

/// A damped sinusoid's parameters as measured.
struct DampedToneEstimate {
  double frequency = 0.0;  ///< damped frequency [Hz]
  double decayRate = 0.0;  ///< β [1/s], amplitude decay rate
};

/// @brief Matrix-pencil estimate (Hua & Sarkar 1990) of one damped sinusoid from the first
///        min(N, maxSamples) samples: pencil L = N/3, SVD, rank 2, root with positive angle.
/// @throws std::invalid_argument if fewer than 16 samples
DampedToneEstimate matrixPencilEstimate(std::span<const float> signal, double sampleRate,
                                        std::size_t maxSamples = 2048);

/// @brief Robust Hilbert decay rate β [1/s]: envelope of the analytic signal (zero-padded by N on
///        both sides), least-squares fit of ln(envelope) over the contiguous run from the peak + 3
///        cycles to 3 cycles before it first falls `fitRangeDecibels` below the peak.
/// @param frequency  the tone's frequency [Hz], for the 3-cycle guards
double hilbertDecayRate(std::span<const float> signal, double sampleRate, double frequency,
                        double fitRangeDecibels = 30.0);

/// One instantaneous-frequency measurement between two rising zero crossings.
struct FrequencyAtTime {
  double time = 0.0;       ///< midpoint of the period [s] from the first sample
  double frequency = 0.0;  ///< 1 / period [Hz]
};

/// @brief Instantaneous frequency from successive upward zero crossings, each located by linear
///        interpolation between the samples that straddle it (≈ 0.1 % per cycle at 3.3 kHz/48 kHz).
std::vector<FrequencyAtTime> zeroCrossingFrequencies(std::span<const float> signal, double sampleRate);

}  // namespace fluidsound::acoustics
