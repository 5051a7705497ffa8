// tests/acoustics/analysis/spectrogram_test.cpp — the pooled STFT power: a tone lands in the row of
// its frequency on linear and log axes, a burst in the columns of its time, and the grid's
// offset in a picture does not move the cells.
#include "acoustics/analysis/spectrogram.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace fluidsound::acoustics {
namespace {

constexpr double kSampleRate = 48000.0;  // Hz

/// A sine of `frequency` [Hz], amplitude 0.5, on during [on, off) s of a `duration` s record.
std::vector<float> toneBurst(double frequency, double duration, double on, double off) {
  std::vector<float> x(static_cast<std::size_t>(std::llround(duration * kSampleRate)), 0.0f);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = static_cast<double>(i) / kSampleRate;
    if (t >= on && t < off)
      x[i] = static_cast<float>(0.5 * std::sin(2.0 * std::numbers::pi * frequency * t));
  }
  return x;
}

SpectrogramLayout layout(int columns, int rows, bool logFrequency) {
  SpectrogramLayout s;
  s.windowSamples = 1024;
  s.hopSamples = 256;
  s.logFrequency = logFrequency;
  s.columns = columns;
  s.rows = rows;
  return s;
}

/// The row whose power summed over the columns is largest.
int loudestRow(const SpectrogramPower& p) {
  int best = -1;
  double bestSum = -1.0;
  for (int r = 0; r < p.rows; ++r) {
    double sum = 0.0;
    for (int c = 0; c < p.columns; ++c) sum += p.at(r, c);
    if (sum > bestSum) bestSum = sum, best = r;
  }
  return best;
}

/// The row a frequency falls in: floor(rows·(1 − u)).
int rowOf(double frequency, const SpectrogramLayout& s) {
  return static_cast<int>(
      std::floor(s.rows * (1.0 - spectrogramAxisFraction(frequency, kSampleRate / 2.0, s))));
}

// Claim: a steady tone's power peaks in the row its frequency maps to, on a linear and a log
// axis. Reference: spectrogramAxisFraction. Tolerance: one row (the Hann main lobe spans ±2 bins
// of 47 Hz, less than one row of 100 rows over 24 kHz; on the log axis ±1 row).
TEST(Spectrogram, ToneLandsInTheRowOfItsFrequency) {
  const std::vector<float> x = toneBurst(3000.0, 0.5, 0.0, 0.5);
  for (const bool log : {false, true}) {
    const SpectrogramLayout s = layout(40, 100, log);
    const SpectrogramPower p = pooledSpectrogramPower(x, kSampleRate, s);
    ASSERT_EQ(p.power.size(), 40u * 100u);
    EXPECT_NEAR(loudestRow(p), rowOf(3000.0, s), 1) << (log ? "log" : "linear");
  }
}

// Claim: a burst on during [0.2, 0.3) s of a 0.5 s record fills the columns of that time only:
// the power at its row is ≥ 10⁴ times larger inside than in the columns well before it (the
// window reaches 1024/2 samples ≈ 11 ms either side). Reference: column c spans c·T/columns.
TEST(Spectrogram, BurstFillsTheColumnsOfItsTime) {
  const std::vector<float> x = toneBurst(3000.0, 0.5, 0.2, 0.3);
  const SpectrogramLayout s = layout(50, 100, false);
  const SpectrogramPower p = pooledSpectrogramPower(x, kSampleRate, s);
  const int row = rowOf(3000.0, s);
  const float inside = p.at(row, 25);  // 0.25 s
  EXPECT_GT(inside, 0.0f);
  for (int c = 0; c < 15; ++c)
    EXPECT_LT(p.at(row, c), 1e-4f * inside) << "column " << c;  // < 0.15 s
}

// Claim: placing the grid at an offset in a picture (left, top) gives the same cells as a grid of
// its own for offsets where the sums are exact, and power for every cell even when frames are
// sparser than columns (a short record in many columns). Reference: the grid at (0, 0).
TEST(Spectrogram, OffsetGridAndSparseFramesFillEveryCell) {
  const std::vector<float> x = toneBurst(1000.0, 0.05, 0.0, 0.05);  // 2400 samples, 10 frames
  SpectrogramLayout s = layout(64, 64, false);
  const SpectrogramPower own = pooledSpectrogramPower(x, kSampleRate, s);
  s.left = 76;
  s.top = 40;
  const SpectrogramPower placed = pooledSpectrogramPower(x, kSampleRate, s);
  EXPECT_EQ(placed.power, own.power);
  const int row = rowOf(1000.0, s);
  for (int c = 0; c < s.columns; ++c) EXPECT_GT(own.at(row, c), 0.0f) << "column " << c;
}

}  // namespace
}  // namespace fluidsound::acoustics
