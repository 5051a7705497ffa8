// acoustics/analysis/spectrogram.h — the short-time Fourier spectrogram of a signal (periodic Hann
// window, Eigen's FFT), its power max-pooled onto a grid of time columns and frequency rows: what
// io/spectrogram_image.h draws (the record: spectrogram_power.h; docs/spectrogram.md).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "acoustics/analysis/spectrogram_power.h"

namespace fluidsound::acoustics {

/// @brief Power spectra of the STFT frames, max-pooled onto the layout's grid. Frame j is centred
///        on sample j·hop (zero-padded at both ends). A column takes the maximum over the frames
///        whose centres fall in it, or, when frames are sparser than columns, the frame nearest
///        to its centre; a row takes the maximum over the FFT bins that fall in it, or, when bins
///        are sparser than rows, the power interpolated linearly at its centre frequency.
/// @param signal      ≥ 1 finite samples (the caller checks them)
/// @param sampleRate  [Hz], > 0
SpectrogramPower pooledSpectrogramPower(std::span<const float> signal, double sampleRate,
                                        const SpectrogramLayout& layout);

}  // namespace fluidsound::acoustics
