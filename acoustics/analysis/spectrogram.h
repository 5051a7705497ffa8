// acoustics/analysis/spectrogram.h — the short-time Fourier spectrogram of a signal (periodic Hann
// window, Eigen's FFT), its power max-pooled onto a grid of time columns and frequency rows: what
// io/spectrogram_image.h draws (docs/spectrogram.md).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace fluidsound::acoustics {

/// The STFT and the grid its power is pooled onto.
struct SpectrogramLayout {
  int windowSamples = 2048;    ///< Hann window length [samples], 16 … 2²⁰
  int hopSamples = 256;        ///< step between windows [samples], ≥ 1
  bool logFrequency = false;   ///< logarithmic frequency axis
  double minFrequency = 20.0;  ///< lower edge of a log axis [Hz], 0 < f < Nyquist
  int columns = 0;             ///< time cells, ≥ 1: column c spans [c, c + 1)·duration/columns
  int rows = 0;                ///< frequency cells, ≥ 2: row 0 at the top (Nyquist)
  /// Where the grid's first column and row sit in a picture [px]. Cell edges are computed as
  /// left + columns·t/duration and top + rows·(1 − u), then floored and offset back, so that the
  /// cells are a picture's pixel columns and rows bit for bit; 0 for a grid of its own.
  int left = 0, top = 0;
};

/// The pooled power of a spectrogram [unit² of the signal, |FFT|²].
struct SpectrogramPower {
  int columns = 0, rows = 0;
  std::vector<float> power;  ///< power[row·columns + column], row 0 at the top (Nyquist)
  float at(int row, int column) const {
    return power[static_cast<std::size_t>(row) * columns + column];
  }
};

/// @brief Axis position u ∈ [0, 1] (0 = bottom, 0 Hz or minFrequency; 1 = Nyquist) of
///        `frequency` [Hz]; −∞ for frequency ≤ 0 on a log axis.
double spectrogramAxisFraction(double frequency, double nyquist, const SpectrogramLayout& layout);

/// @brief The frequency [Hz] at axis position u (the inverse of spectrogramAxisFraction).
double spectrogramAxisFrequency(double u, double nyquist, const SpectrogramLayout& layout);

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
