// Tests of io::writeAudio's loudness normalisation (io/audio_file.h, docs/audio.md "Loudness"):
// the file written reaches the LUFS target when measured independently, whatever the render's
// level, the true-peak ceiling lowers the gain, and the report gives the loudness written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "io/loudness.h"
#include "io/audio_file.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

/// Three seconds of a 1 kHz sine of peak `amplitude` in two channels, the second at half level.
AudioBuffer sine(double amplitude) {
  AudioBuffer audio;
  audio.sampleRate = 48000.0;
  audio.channels.assign(2, std::vector<float>(3 * 48000));
  for (std::size_t i = 0; i < audio.channels[0].size(); ++i) {
    const double x =
        amplitude * std::sin(2 * std::numbers::pi * 1000.0 * static_cast<double>(i) / 48000.0);
    audio.channels[0][i] = static_cast<float>(x);
    audio.channels[1][i] = static_cast<float>(0.5 * x);
  }
  return audio;
}

io::LoudnessMeasurement measuredFile(const fs::path& path) {
  const AudioBuffer read = readAudio(path);
  return io::measureLoudness(read.channels, read.sampleRate);
}

// Claim: with a loudness target the file written measures at the target, for float and 16-bit
// PCM, and for renders at any level in pascals: 0.5 Pa and 10 µPa, the latter far below BS.1770's
// −70 LUFS absolute gate at its own scale (the writer measures with the peak at full scale,
// audio_file.cpp). Reference: the target, −23 LUFS (EBU R 128), measured on the file read back.
// Tolerance ±0.1 LU: EBU Tech 3341's meter accuracy (the 16-bit dither adds noise 70 dB down,
// < 0.001 LU). The report's loudness of what was written is that same measurement (±0.01 LU:
// the writer meters the samples it hands libsndfile, which are the samples read back).
TEST(AudioFileLoudness, TheFileWrittenMeetsTheTargetAtAnyRenderLevel) {
  const test::TempFolder folder;
  for (const double pascals : {0.5, 1e-5}) {
    for (const int bits : {32, 16}) {
      const fs::path path = folder.path() / ("out" + std::to_string(bits) + ".wav");
      AudioWriteSettings settings;
      settings.bitsPerSample = bits;
      settings.loudness = io::LoudnessTarget{-23.0, -1.0};
      const AudioWriteReport report = writeAudio(path, sine(pascals), settings);
      const io::LoudnessMeasurement m = measuredFile(path);
      ASSERT_TRUE(m.integratedLufs.has_value()) << pascals << " Pa, " << bits << " bits";
      EXPECT_NEAR(*m.integratedLufs, -23.0, 0.1) << pascals << " Pa, " << bits << " bits";
      ASSERT_TRUE(report.written.integratedLufs.has_value());
      EXPECT_NEAR(*report.written.integratedLufs, *m.integratedLufs, 0.01);
      EXPECT_FALSE(report.truePeakLimited);
      EXPECT_FALSE(report.loudnessUnmeasured);
    }
  }
}

// Claim: when the target's gain would put the true peak above the ceiling, the gain is lowered so
// the true peak sits at the ceiling and the report says so. Reference: a 1 kHz sine of crest A in
// one channel and A/2 in the other has loudness 20·log10 A + 10·log10(5/8) = crest − 2.04 dB
// (BS.1770 at 1 kHz, where K-weighting's +0.691 dB cancels its −0.691 offset: Tech 3341 case 1),
// so −3 LUFS under a −6 dBTP ceiling cannot be met: the crest goes to −6 dBTP and the loudness to
// −8.04 LUFS. Tolerance: Tech 3341's +0.2/−0.4 dB for true peak, ±0.1 LU for loudness.
TEST(AudioFileLoudness, TheTruePeakCeilingLowersTheGain) {
  const test::TempFolder folder;
  const fs::path path = folder.path() / "loud.wav";
  AudioWriteSettings settings;
  settings.loudness = io::LoudnessTarget{-3.0, -6.0};
  const AudioWriteReport report = writeAudio(path, sine(0.2), settings);
  EXPECT_TRUE(report.truePeakLimited);
  const io::LoudnessMeasurement m = measuredFile(path);
  EXPECT_LE(m.truePeakDbtp, -6.0 + 0.2);
  EXPECT_GE(m.truePeakDbtp, -6.0 - 0.4);
  ASSERT_TRUE(m.integratedLufs.has_value());
  EXPECT_NEAR(*m.integratedLufs, -6.0 + 10 * std::log10(5.0 / 8.0), 0.1);
}

// Claim: without normalisation the samples keep their pascals (gain exactly 1) and the report
// still measures them; silence has no loudness to normalise (gain 1, flagged); peak and
// loudness normalisation together are refused before anything is written.
TEST(AudioFileLoudness, CalibratedBySilenceFlaggedAndConflictsRefused) {
  const test::TempFolder folder;
  const AudioWriteReport calibrated = writeAudio(folder.path() / "pa.wav", sine(0.5), {});
  EXPECT_EQ(calibrated.gain, 1.0);
  ASSERT_TRUE(calibrated.written.integratedLufs.has_value());
  EXPECT_NEAR(*calibrated.written.integratedLufs,
              *measuredFile(folder.path() / "pa.wav").integratedLufs, 0.01);

  AudioBuffer silence = sine(0.0);
  AudioWriteSettings loudness;
  loudness.loudness = io::LoudnessTarget{};
  const AudioWriteReport silent = writeAudio(folder.path() / "silent.wav", silence, loudness);
  EXPECT_EQ(silent.gain, 1.0);
  EXPECT_TRUE(silent.loudnessUnmeasured);

  AudioWriteSettings both = loudness;
  both.normalizePeakDbfs = -1.0;
  EXPECT_THROW(writeAudio(folder.path() / "both.wav", sine(0.5), both), std::invalid_argument);
  EXPECT_FALSE(fs::exists(folder.path() / "both.wav"));
}

}  // namespace
}  // namespace fluidsound::io
