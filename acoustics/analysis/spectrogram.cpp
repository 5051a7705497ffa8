// acoustics/analysis/spectrogram.cpp — see spectrogram.h.
#include "acoustics/analysis/spectrogram.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <unsupported/Eigen/FFT>

namespace fluidsound::acoustics {
namespace {

/// The STFT frames [first, last] pooled into each column, monotone in the column.
struct ColumnFrames {
  std::vector<std::int64_t> first, last;
};

ColumnFrames framesOfColumns(std::int64_t sampleCount, double sampleRate,
                             const SpectrogramLayout& s) {
  const std::int64_t hop = s.hopSamples;
  const std::int64_t frameCount = (sampleCount - 1) / hop + 1;
  const double duration = static_cast<double>(sampleCount) / sampleRate;
  const auto columnOfFrame = [&](std::int64_t j) {
    const double x = s.left + s.columns * ((static_cast<double>(j * hop) / sampleRate) / duration);
    return std::clamp(static_cast<int>(std::floor(x)) - s.left, 0, s.columns - 1);
  };
  ColumnFrames out{std::vector<std::int64_t>(s.columns, -1),
                   std::vector<std::int64_t>(s.columns, -1)};
  for (std::int64_t j = 0; j < frameCount; ++j) {
    const int c = columnOfFrame(j);
    if (out.first[c] < 0) out.first[c] = j;
    out.last[c] = j;
  }
  for (int c = 0; c < s.columns; ++c) {
    if (out.first[c] >= 0) continue;
    const double centreTime = duration * (c + 0.5) / s.columns;
    const auto nearest = static_cast<std::int64_t>(std::llround(centreTime * sampleRate / hop));
    out.first[c] = out.last[c] = std::clamp<std::int64_t>(nearest, 0, frameCount - 1);
  }
  return out;
}

/// Where each FFT bin goes: its row (−1: off the axis), the bins per row and, for the rows no bin
/// falls in, the lower bin and the upper bin's weight of the linear interpolation.
struct BinRows {
  struct Interpolation {
    int lowerBin;
    float upperWeight;
  };
  std::vector<int> rowOfBin, binsInRow;
  std::vector<Interpolation> interpolation;
};

BinRows rowsOfBins(double sampleRate, const SpectrogramLayout& s) {
  const int binCount = s.windowSamples / 2 + 1;
  const double binWidth = sampleRate / s.windowSamples;  // Hz
  const double nyquist = sampleRate / 2.0;
  BinRows out{std::vector<int>(binCount, -1), std::vector<int>(s.rows, 0),
              std::vector<BinRows::Interpolation>(s.rows)};
  for (int b = 0; b < binCount; ++b) {
    const double y = s.top + s.rows * (1.0 - spectrogramAxisFraction(b * binWidth, nyquist, s));
    if (!std::isfinite(y) || y > s.top + s.rows) continue;  // below a log axis
    const int row = static_cast<int>(std::floor(y)) - s.top;
    out.rowOfBin[b] = std::clamp(row, 0, s.rows - 1);  // the axis' bottom edge joins the last row
    ++out.binsInRow[out.rowOfBin[b]];
  }
  for (int row = 0; row < s.rows; ++row) {
    const double u = (s.rows - row - 0.5) / s.rows;
    const double bin =
        std::clamp(spectrogramAxisFrequency(u, nyquist, s) / binWidth, 0.0, binCount - 1.0);
    const int lower = std::min(static_cast<int>(bin), binCount - 2);
    out.interpolation[row] = {lower, static_cast<float>(bin - lower)};
  }
  return out;
}

/// The power spectrum |X_b|² of STFT frame j, the last one kept (columns may share a frame).
class FramePower {
 public:
  FramePower(std::span<const float> signal, const SpectrogramLayout& s)
      : signal_(signal),
        hop_(s.hopSamples),
        hann_(s.windowSamples),
        frame_(s.windowSamples),
        power_(s.windowSamples / 2 + 1) {
    // Periodic Hann window (the DFT-even form, exact for spectral analysis).
    const int window = s.windowSamples;
    for (int i = 0; i < window; ++i)
      hann_[i] = static_cast<float>(0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * i / window));
    fft_.SetFlag(Eigen::FFT<float>::HalfSpectrum);
  }

  const std::vector<float>& of(std::int64_t j) {
    if (j == cached_) return power_;
    const auto n = static_cast<std::int64_t>(signal_.size());
    const int window = static_cast<int>(hann_.size());
    const std::int64_t start = j * hop_ - window / 2;
    for (int i = 0; i < window; ++i) {
      const std::int64_t k = start + i;
      frame_[i] = (k >= 0 && k < n) ? hann_[i] * signal_[k] : 0.0f;
    }
    fft_.fwd(spectrum_, frame_);
    for (std::size_t b = 0; b < power_.size(); ++b) power_[b] = std::norm(spectrum_[b]);
    cached_ = j;
    return power_;
  }

 private:
  std::span<const float> signal_;
  std::int64_t hop_;
  std::vector<float> hann_, frame_, power_;
  std::vector<std::complex<float>> spectrum_;
  Eigen::FFT<float> fft_;
  std::int64_t cached_ = -1;
};

}  // namespace

double spectrogramAxisFraction(double frequency, double nyquist, const SpectrogramLayout& layout) {
  if (!layout.logFrequency) return frequency / nyquist;
  if (frequency <= 0.0) return -std::numeric_limits<double>::infinity();
  return std::log(frequency / layout.minFrequency) / std::log(nyquist / layout.minFrequency);
}

double spectrogramAxisFrequency(double u, double nyquist, const SpectrogramLayout& layout) {
  if (!layout.logFrequency) return u * nyquist;
  return layout.minFrequency * std::pow(nyquist / layout.minFrequency, u);
}

SpectrogramPower pooledSpectrogramPower(std::span<const float> signal, double sampleRate,
                                        const SpectrogramLayout& layout) {
  const int width = layout.columns, height = layout.rows;
  const ColumnFrames frames =
      framesOfColumns(static_cast<std::int64_t>(signal.size()), sampleRate, layout);
  const BinRows bins = rowsOfBins(sampleRate, layout);
  const int binCount = static_cast<int>(bins.rowOfBin.size());
  FramePower framePower(signal, layout);
  std::vector<float> columnPower(binCount);

  SpectrogramPower out{width, height,
                       std::vector<float>(static_cast<std::size_t>(width) * height, 0.0f)};
  std::vector<float>& power = out.power;
  for (int c = 0; c < width; ++c) {
    std::fill(columnPower.begin(), columnPower.end(), 0.0f);
    for (std::int64_t j = frames.first[c]; j <= frames.last[c]; ++j) {
      const std::vector<float>& p = framePower.of(j);
      for (int b = 0; b < binCount; ++b) columnPower[b] = std::max(columnPower[b], p[b]);
    }
    for (int row = 0; row < height; ++row) {
      if (bins.binsInRow[row] > 0) continue;
      const auto [lower, w] = bins.interpolation[row];
      power[row * width + c] = (1.0f - w) * columnPower[lower] + w * columnPower[lower + 1];
    }
    for (int b = 0; b < binCount; ++b) {
      if (bins.rowOfBin[b] < 0) continue;
      float& p = power[bins.rowOfBin[b] * width + c];
      p = std::max(p, columnPower[b]);
    }
  }
  return out;
}

}  // namespace fluidsound::acoustics
