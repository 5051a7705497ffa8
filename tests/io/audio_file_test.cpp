// tests/io/audio_file_test.cpp — WAV/FLAC writing and reading: float is bit-exact, PCM is within
// its quantisation and dither, normalisation hits the requested peak, clipping is counted.
#include "io/audio_file.h"

#include <gtest/gtest.h>
#include <sndfile.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "io/input_error.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

using test::TempFolder;

/// Two channels, one second at 48 kHz: a 997 Hz sine (peak `amplitude`) and its negative plus a
/// little noise, so that every code of the quantiser's neighbourhood is visited.
AudioBuffer testSignal(double amplitude) {
  AudioBuffer audio;
  audio.sampleRate = 48000.0;
  audio.channels.assign(2, std::vector<float>(48000));
  std::mt19937_64 generator(7);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  for (std::size_t i = 0; i < 48000; ++i) {
    const double sine =
        amplitude * std::sin(2 * std::numbers::pi * 997.0 * static_cast<double>(i) / 48000.0);
    audio.channels[0][i] = static_cast<float>(sine);
    audio.channels[1][i] = static_cast<float>(-0.5 * sine + noise(generator));
  }
  return audio;
}

/// The libsndfile format (major | subtype) of a file, to check what was really written.
int storedFormat(const fs::path& path) {
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  if (file == nullptr) return 0;
  sf_close(file);
  return info.format;
}

double peakOf(const AudioBuffer& audio) {
  double peak = 0;
  for (const auto& channel : audio.channels)
    for (float v : channel) peak = std::max(peak, static_cast<double>(std::abs(v)));
  return peak;
}

/// Claim (Lipshitz, Wannamaker & Vanderkooy 1992, "Quantization and dither: a theoretical survey",
/// JAES 40(5)): with TPDF dither of ±1 LSB peak, the total error q − x is bounded by 1.5 LSB
/// (1 LSB dither + 0.5 LSB rounding), has mean 0 and variance Δ²/4 (Δ²/12 rounding + Δ²/6
/// dither), independent of the signal.
/// Tolerances: over N = 96000 samples the standard error of the mean is 0.5/√N ≈ 0.0016 LSB and
/// of the mean square about √(0.1/N)/0.25 ≈ 0.4 % (fourth moment of a sum of three uniforms);
/// the bounds below are about 10 standard errors wide, so the test fails only on a real bias.
void expectDitheredQuantisation(const AudioBuffer& written, const AudioBuffer& read, int bits) {
  const double lsb = std::ldexp(1.0, -(bits - 1));
  ASSERT_EQ(read.channels.size(), written.channels.size());
  double sum = 0, sumSquares = 0, largest = 0;
  std::size_t count = 0;
  for (std::size_t c = 0; c < written.channels.size(); ++c) {
    ASSERT_EQ(read.channels[c].size(), written.channels[c].size());
    for (std::size_t i = 0; i < written.channels[c].size(); ++i) {
      const double error =
          (static_cast<double>(read.channels[c][i]) - written.channels[c][i]) / lsb;
      sum += error;
      sumSquares += error * error;
      largest = std::max(largest, std::abs(error));
      ++count;
    }
  }
  const double mean = sum / static_cast<double>(count);
  const double meanSquare = sumSquares / static_cast<double>(count);
  EXPECT_LE(largest, 1.5) << "largest error in LSB";
  EXPECT_NEAR(mean, 0.0, 0.02) << "mean error in LSB";
  EXPECT_NEAR(meanSquare, 0.25, 0.04 * 0.25) << "mean-square error in LSB²";
}

/// What a round trip through a file shows: the test signal written (peak 0.9, below full scale),
/// the format libsndfile finds in the file (major | subtype), and the samples read back.
struct RoundTrip {
  AudioBuffer written;
  int format = 0;
  AudioBuffer read;
};

/// Writes testSignal(0.9) as `fileName` in a fresh folder with `settings` and reads it back.
RoundTrip roundTrip(const std::string& fileName, const AudioWriteSettings& settings) {
  TempFolder folder;
  const fs::path path = folder.path() / fileName;
  RoundTrip trip;
  trip.written = testSignal(0.9);
  writeAudio(path, trip.written, settings);
  trip.format = storedFormat(path);
  trip.read = readAudio(path);
  return trip;
}

TEST(AudioFile, FloatWavRoundTripIsBitExact) {
  // Claim: 32-bit float WAV stores the samples as given (pascals, beyond ±1 too), so reading
  // gives back the same floats exactly; tolerance zero.
  TempFolder folder;
  const fs::path path = folder.path() / "render.wav";
  AudioBuffer audio = testSignal(3.5);  // 3.5 Pa: far beyond full scale, and must not clip
  audio.sampleRate = 44100.0;
  const AudioWriteReport report = writeAudio(path, audio, {});
  EXPECT_EQ(storedFormat(path), SF_FORMAT_WAV | SF_FORMAT_FLOAT);
  const AudioBuffer read = readAudio(path);
  EXPECT_EQ(read.sampleRate, 44100.0);
  EXPECT_EQ(read.channels, audio.channels);
  EXPECT_EQ(report.gain, 1.0);
  EXPECT_EQ(report.clippedSamples, 0);
  EXPECT_EQ(report.inputPeak, peakOf(audio));
  EXPECT_NEAR(report.outputPeakDbfs, 20 * std::log10(peakOf(audio)), 1e-9);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"render.wav"});
}

TEST(AudioFile, TheSameAudioWrittenTwiceGivesTheSameBytes) {
  // Claim: a float WAV holds nothing but the format and the samples — no PEAK chunk, which
  // libsndfile stamps with the time of writing — so the same render written twice, a second
  // apart, is the same file byte for byte (the brief: same input and seed, same bits).
  TempFolder folder;
  const AudioBuffer audio = testSignal(0.5);
  writeAudio(folder.path() / "a.wav", audio, {});
  std::this_thread::sleep_for(
      std::chrono::milliseconds(1100));  // the chunk's clock ticks in seconds
  writeAudio(folder.path() / "b.wav", audio, {});
  const auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string a = bytes(folder.path() / "a.wav");
  EXPECT_EQ(a.find("PEAK"), std::string::npos) << "a PEAK chunk";
  EXPECT_TRUE(a == bytes(folder.path() / "b.wav"))
      << "the two files differ";  // not printed: binary
}

TEST(AudioFile, Pcm16RoundTripIsWithinQuantisationAndDither) {
  AudioWriteSettings settings;
  settings.bitsPerSample = 16;
  const RoundTrip trip = roundTrip("render.wav", settings);
  EXPECT_EQ(trip.format, SF_FORMAT_WAV | SF_FORMAT_PCM_16);
  expectDitheredQuantisation(trip.written, trip.read, 16);
}

TEST(AudioFile, Pcm24RoundTripIsWithinQuantisationAndDither) {
  AudioWriteSettings settings;
  settings.bitsPerSample = 24;
  const RoundTrip trip = roundTrip("render.wav", settings);
  EXPECT_EQ(trip.format, SF_FORMAT_WAV | SF_FORMAT_PCM_24);
  expectDitheredQuantisation(trip.written, trip.read, 24);
}

TEST(AudioFile, FlacRoundTripIsWithin24BitPrecision) {
  // FLAC has no float samples: the default 32 bits become 24-bit PCM (docs/audio.md).
  const std::string fileName = "render.flac";
  AudioWriteSettings settings;
  settings.format = audioFormatFromPath(fileName).value();
  const RoundTrip trip = roundTrip(fileName, settings);
  EXPECT_EQ(trip.format, SF_FORMAT_FLAC | SF_FORMAT_PCM_24);
  EXPECT_EQ(trip.read.sampleRate, 48000.0);
  expectDitheredQuantisation(trip.written, trip.read, 24);
}

TEST(AudioFile, Flac16IsWrittenAs16BitPcm) {
  AudioWriteSettings settings;
  settings.format = AudioFormat::Flac;
  settings.bitsPerSample = 16;
  const RoundTrip trip = roundTrip("render.flac", settings);
  EXPECT_EQ(trip.format, SF_FORMAT_FLAC | SF_FORMAT_PCM_16);
  expectDitheredQuantisation(trip.written, trip.read, 16);
}

TEST(AudioFile, NormalisationPutsThePeakAtTheRequestedLevel) {
  // Claim: the written peak is at normalizePeakDbfs. Float WAV: exact up to float rounding
  // (1e-7 relative ≈ 1e-6 dB); the requirement is 0.01 dB.
  TempFolder folder;
  const fs::path path = folder.path() / "render.wav";
  const AudioBuffer audio = testSignal(0.02);  // a quiet render: 0.02 Pa
  AudioWriteSettings settings;
  settings.normalizePeakDbfs = -1.0;
  const AudioWriteReport report = writeAudio(path, audio, settings);
  const double readPeakDbfs = 20 * std::log10(peakOf(readAudio(path)));
  EXPECT_NEAR(readPeakDbfs, -1.0, 0.01);
  EXPECT_NEAR(report.outputPeakDbfs, -1.0, 0.01);
  EXPECT_EQ(report.inputPeak, peakOf(audio));
  EXPECT_NEAR(report.gain, std::pow(10.0, -1.0 / 20) / peakOf(audio), 1e-12 * report.gain);
}

TEST(AudioFile, NormalisationOfPcmPutsThePeakAtTheRequestedLevel) {
  // 24-bit: the peak moves by at most 1.5 LSB = 1.8e-7 of full scale ≈ 2e-6 dB at −3 dBFS.
  TempFolder folder;
  const fs::path path = folder.path() / "render.wav";
  const AudioBuffer audio = testSignal(250.0);  // a loud render: 250 Pa
  AudioWriteSettings settings;
  settings.bitsPerSample = 24;
  settings.normalizePeakDbfs = -3.0;
  const AudioWriteReport report = writeAudio(path, audio, settings);
  EXPECT_NEAR(20 * std::log10(peakOf(readAudio(path))), -3.0, 0.01);
  EXPECT_NEAR(report.outputPeakDbfs, -3.0, 0.01);
  EXPECT_EQ(report.clippedSamples, 0);
}

TEST(AudioFile, NormalisingSilenceLeavesItSilent) {
  TempFolder folder;
  AudioBuffer audio;
  audio.channels.assign(1, std::vector<float>(100, 0.0f));
  AudioWriteSettings settings;
  settings.normalizePeakDbfs = -1.0;
  const AudioWriteReport report = writeAudio(folder.path() / "silence.wav", audio, settings);
  EXPECT_EQ(report.gain, 1.0);
  EXPECT_EQ(report.inputPeak, 0.0);
  EXPECT_EQ(report.outputPeakDbfs, -std::numeric_limits<double>::infinity());
}

TEST(AudioFile, PcmClippingIsCountedAndReported) {
  // 1.5 and −2.0 are beyond full scale; 0.999 is 31 LSB below it, beyond the reach of dither.
  TempFolder folder;
  const fs::path path = folder.path() / "loud.wav";
  AudioBuffer audio;
  audio.channels = {{0.5f, 1.5f, -2.0f, -0.25f, 0.999f}};
  AudioWriteSettings settings;
  settings.bitsPerSample = 16;
  const AudioWriteReport report = writeAudio(path, audio, settings);
  EXPECT_EQ(report.clippedSamples, 2);
  EXPECT_EQ(report.inputPeak, 2.0);
  EXPECT_EQ(report.outputPeakDbfs, 0.0);  // −32768 / 32768
  const AudioBuffer read = readAudio(path);
  EXPECT_EQ(read.channels[0][1], 32767.0f / 32768.0f);
  EXPECT_EQ(read.channels[0][2], -1.0f);
}

TEST(AudioFile, FloatWavIsNeverClipped) {
  TempFolder folder;
  AudioBuffer audio;
  audio.channels = {{0.5f, 1.5f, -2.0f}};
  const AudioWriteReport report = writeAudio(folder.path() / "loud.wav", audio, {});
  EXPECT_EQ(report.clippedSamples, 0);
  EXPECT_EQ(readAudio(folder.path() / "loud.wav").channels, audio.channels);
}

TEST(AudioFile, DitherIsDeterminedByItsSeed) {
  TempFolder folder;
  const AudioBuffer audio = testSignal(0.5);
  AudioWriteSettings settings;
  settings.bitsPerSample = 16;
  settings.ditherSeed = 42;
  writeAudio(folder.path() / "a.wav", audio, settings);
  writeAudio(folder.path() / "b.wav", audio, settings);
  settings.ditherSeed = 43;
  writeAudio(folder.path() / "c.wav", audio, settings);
  const AudioBuffer a = readAudio(folder.path() / "a.wav");
  EXPECT_EQ(a.channels, readAudio(folder.path() / "b.wav").channels);
  EXPECT_NE(a.channels, readAudio(folder.path() / "c.wav").channels);
}

TEST(AudioFile, BadSettingsAreRejectedBeforeWriting) {
  TempFolder folder;
  const fs::path path = folder.path() / "render.wav";
  const AudioBuffer good = testSignal(0.5);
  AudioWriteSettings badBits;
  badBits.bitsPerSample = 20;
  EXPECT_THROW(writeAudio(path, good, badBits), std::invalid_argument);
  AudioBuffer uneven = good;
  uneven.channels[1].pop_back();
  EXPECT_THROW(writeAudio(path, uneven, {}), std::invalid_argument);
  AudioBuffer notANumber = good;
  notANumber.channels[0][10] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(writeAudio(path, notANumber, {}), std::invalid_argument);
  AudioBuffer fractionalRate = good;
  fractionalRate.sampleRate = 44100.5;
  EXPECT_THROW(writeAudio(path, fractionalRate, {}), std::invalid_argument);
  EXPECT_THROW(writeAudio(path, AudioBuffer{}, {}), std::invalid_argument);
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AudioFile, WritingIntoAMissingFolderIsAnOutputErrorNamingThePath) {
  TempFolder folder;
  const fs::path path = folder.path() / "missing" / "render.wav";
  try {
    writeAudio(path, testSignal(0.5), {});
    FAIL() << "no OutputError";
  } catch (const OutputError& error) {
    EXPECT_TRUE(std::string(error.what()).starts_with(path.string() + ": cannot write"))
        << error.what();
  }
}

TEST(AudioFile, ReadingAMissingFileIsAnInputErrorNamingIt) {
  TempFolder folder;
  const fs::path path = folder.path() / "nope.wav";
  try {
    readAudio(path);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              path.string() + ": expected a readable file, found no such file");
  }
}

TEST(AudioFile, ReadingANonAudioFileIsAnInputErrorNamingIt) {
  TempFolder folder;
  const fs::path path = folder.path() / "notes.wav";
  { std::ofstream(path) << "these are not samples"; }
  try {
    readAudio(path);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.file(), path.string());
    EXPECT_TRUE(message.starts_with(path.string() + ": expected an audio file")) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(AudioFile, FormatFollowsTheFileExtension) {
  EXPECT_EQ(audioFormatFromPath("out/render.flac"), AudioFormat::Flac);
  EXPECT_EQ(audioFormatFromPath("RENDER.FLAC"), AudioFormat::Flac);
  EXPECT_EQ(audioFormatFromPath("render.wav"), AudioFormat::Wav);
  EXPECT_EQ(audioFormatFromPath("render.WAV"), AudioFormat::Wav);
  // No guess: a name libsndfile would not write as WAV or FLAC has no format (the CLI refuses it).
  EXPECT_EQ(audioFormatFromPath("render"), std::nullopt);
  EXPECT_EQ(audioFormatFromPath("render.mp3"), std::nullopt);
  EXPECT_EQ(audioFormatFromPath("render.wav.tmp"), std::nullopt);
}

}  // namespace
}  // namespace fluidsound::io
