// io/spectrogram_image.h — the picture of a sound: a short-time Fourier spectrogram rendered to a
// PNG with labelled time and frequency axes (units) and a dB colour bar.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

#include "acoustics/analysis/spectrogram_power.h"
#include "io/audio_file.h"

namespace fluidsound::io {

struct SpectrogramSettings {
  int windowSamples = 2048;         ///< Hann window length [samples]
  int hopSamples = 256;             ///< step between windows [samples]
  bool logFrequency = false;        ///< logarithmic frequency axis
  double minFrequency = 20.0;       ///< lower edge of a log axis [Hz]
  double dynamicRangeDb = 90.0;     ///< colours span [peak − range, peak] dB
  int width = 1200;                 ///< image width [px]
  int height = 600;                 ///< image height [px]
  int channel = -1;                 ///< channel to draw; −1 = mean of all channels
};

/// @brief The signal the picture of `audio` shows: channel settings.channel, or the sample-wise
///        mean of all channels (channel < 0).
/// @throws std::invalid_argument for empty audio, channels of different lengths, a non-finite
///         sample or sample rate, or bad settings (window outside 16…2²⁰, hop < 1, dynamic range
///         ≤ 0, channel out of range, image smaller than spectrogramMinimumSize or larger than
///         16384 px, log axis with minFrequency outside (0, Nyquist))
std::vector<float> spectrogramSignal(const AudioBuffer& audio, const SpectrogramSettings& settings);

/// @brief The grid of the picture's plot area that the spectrogram's power is pooled onto
///        (acoustics::pooledSpectrogramPower): one cell per pixel.
acoustics::SpectrogramLayout spectrogramLayout(const SpectrogramSettings& settings);

/// @brief The PNG of the pooled spectrogram `power` of `audio` (on spectrogramLayout(settings)),
///        titled `title`, as bytes; for callers that write several outputs all or nothing
///        (io::OutputBatch).
/// @throws std::invalid_argument as spectrogramSignal(), or for power of another grid
std::string encodeSpectrogramPng(const AudioBuffer& audio, const SpectrogramSettings& settings,
                                 const std::string& title, const acoustics::SpectrogramPower& power);

/// @brief Writes encodeSpectrogramPng()'s bytes to `path` by the output rule of output_file.h.
/// @param title  first line of the picture; empty: the PNG's file name
/// @throws OutputError if the PNG cannot be written; else as encodeSpectrogramPng()
void writeSpectrogramPng(const std::filesystem::path& path, const AudioBuffer& audio,
                         const SpectrogramSettings& settings, const std::string& title,
                         const acoustics::SpectrogramPower& power);

// The picture's geometry and colours, public so that tests (and callers that annotate the
// picture) use the same mapping as the renderer.

/// The rectangle of the picture that holds the spectrogram itself [px]; x right, y down from
/// the top-left corner of the image. The remaining margins hold the title, axes and colour bar.
struct SpectrogramPlotArea {
  int left = 0, top = 0, width = 0, height = 0;  ///< [px]
};

/// Smallest image (width, height) [px] that leaves room for the labels and a 64 × 64 px plot.
std::array<int, 2> spectrogramMinimumSize();

/// @brief The plot area for an image of settings.width × settings.height pixels.
SpectrogramPlotArea spectrogramPlotArea(const SpectrogramSettings& settings);

/// @brief Image y coordinate [px, continuous, 0 = top edge of the image] of `frequency` [Hz] on
///        the frequency axis: 0 Hz (linear) or minFrequency (log) at the bottom edge of the plot
///        area, the Nyquist frequency sampleRate/2 [Hz] at its top edge. The pixel row that
///        draws `frequency` is floor(y). Frequencies off the axis give y outside the plot area.
double frequencyToPixelRow(double frequency, double sampleRate,
                           const SpectrogramSettings& settings);

/// @brief Image x coordinate [px, continuous] of `time` [s] on the time axis: 0 s at the left
///        edge of the plot area, `duration` [s] (the audio's length) at its right edge. The pixel
///        column that draws `time` is floor(x).
double timeToPixelColumn(double time, double duration, const SpectrogramSettings& settings);

/// @brief The colour map: `level` in [0, 1] (0 = peak − dynamic range, 1 = peak) → sRGB.
///        Perceptually ordered: CIE L* rises monotonically from black (0) to pale yellow (98).
std::array<std::uint8_t, 3> spectrogramColour(double level);

}  // namespace fluidsound::io
