// acoustics/analysis/spectrogram_power.h — the spectrogram as a record: the grid of time columns
// and frequency rows its power is pooled onto (and where a frequency sits on that axis), and the
// pooled power itself. acoustics/analysis/spectrogram.h computes it; io/spectrogram_image.h draws
// it (docs/spectrogram.md).
#pragma once

#include <cstddef>
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

}  // namespace fluidsound::acoustics
