// Tests of io/channel_layout.h through io::writeAudio: read back byte by byte, a WAV or FLAC with
// 3 or more listeners says "no speaker positions" (not quad, 5.1 or 7.1), a WAV names its
// channels after the listeners, mono and stereo keep their plain layout, and the samples are
// what libsndfile reads back.
#include "io/channel_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "io/audio_file.h"
#include "support/file_bytes.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

using test::fileBytes;

std::uint32_t le32(const std::string& b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24);
}

/// The body of the first RIFF chunk `id` of a WAV file, if any.
std::optional<std::string> waveChunk(const std::string& wav, const char* id) {
  for (std::size_t at = 12; at + 8 <= wav.size();) {
    const std::uint32_t size = le32(wav, at + 4);
    if (wav.compare(at, 4, id) == 0) return wav.substr(at + 8, size);
    at += 8 + size + (size & 1u);
  }
  return std::nullopt;
}

/// The Vorbis comments of a FLAC file (RFC 9639, metadata blocks), read from its metadata blocks.
std::vector<std::string> flacComments(const std::string& flac) {
  std::vector<std::string> comments;
  std::size_t at = 4;
  for (bool last = false; !last && at + 4 <= flac.size();) {
    const auto header = static_cast<unsigned char>(flac[at]);
    last = (header & 0x80) != 0;
    const std::size_t length = (std::size_t{static_cast<unsigned char>(flac[at + 1])} << 16) |
                               (std::size_t{static_cast<unsigned char>(flac[at + 2])} << 8) |
                               static_cast<unsigned char>(flac[at + 3]);
    if ((header & 0x7f) == 4) {
      std::size_t p = at + 4;
      p += 4 + le32(flac, p);  // vendor
      const std::uint32_t count = le32(flac, p);
      p += 4;
      for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t n = le32(flac, p);
        comments.push_back(flac.substr(p + 4, n));
        p += 4 + n;
      }
    }
    at += 4 + length;
  }
  return comments;
}

AudioBuffer ramps(std::size_t channels) {
  AudioBuffer audio;
  audio.sampleRate = 48000.0;
  audio.channels.assign(channels, std::vector<float>(4800));
  for (std::size_t c = 0; c < channels; ++c)
    for (std::size_t i = 0; i < 4800; ++i)
      audio.channels[c][i] =
          static_cast<float>(0.1 * static_cast<double>(c + 1) * std::sin(0.01 * i * (c + 1)));
  return audio;
}

std::vector<std::string> names(std::size_t channels) {
  std::vector<std::string> n;
  for (std::size_t c = 0; c < channels; ++c) n.push_back("mic " + std::to_string(c));
  return n;
}

// Claim: WAV files of 3 to 8 channels are WAVE_FORMAT_EXTENSIBLE (tag 0xFFFE) with
// dwChannelMask 0 — "no speaker positions" (Microsoft, "Multiple channel audio data and WAVE
// files") — so no player reads 4, 6 or 8 listeners as quad, 5.1 or 7.1 (libsndfile's masks
// 0x33, 0x3F, 0xFF without the fix); float samples read back bit for bit. Reference: the bytes.
TEST(ChannelLayout, WavFromThreeChannelsOnHasNoSpeakerMask) {
  const test::TempFolder folder;
  for (std::size_t channels = 3; channels <= 8; ++channels) {
    const fs::path path = folder.path() / ("c" + std::to_string(channels) + ".wav");
    AudioWriteSettings settings;
    settings.channelNames = names(channels);
    const AudioBuffer audio = ramps(channels);
    writeAudio(path, audio, settings);
    const std::optional<std::string> fmt = waveChunk(fileBytes(path), "fmt ");
    ASSERT_TRUE(fmt.has_value());
    ASSERT_GE(fmt->size(), 40u);
    EXPECT_EQ(static_cast<unsigned char>((*fmt)[0]) | (static_cast<unsigned char>((*fmt)[1]) << 8),
              0xFFFE)
        << channels << " channels";
    EXPECT_EQ(le32(*fmt, 20), 0u) << channels << " channels: speaker mask";
    EXPECT_EQ(readAudio(path).channels, audio.channels) << channels << " channels";
  }
}

// Claim: mono and stereo keep plain WAVE (PCM or float tag 3), whose meaning every player agrees
// on (one listener; a left/right pair). Reference: the format tag in the bytes.
TEST(ChannelLayout, MonoAndStereoWavStayPlain) {
  const test::TempFolder folder;
  for (std::size_t channels = 1; channels <= 2; ++channels) {
    const fs::path path = folder.path() / ("c" + std::to_string(channels) + ".wav");
    writeAudio(path, ramps(channels), {});
    const std::optional<std::string> fmt = waveChunk(fileBytes(path), "fmt ");
    ASSERT_TRUE(fmt.has_value());
    EXPECT_EQ(static_cast<unsigned char>((*fmt)[0]), 3)
        << "IEEE float, " << channels << " channels";
  }
}

// Claim: the WAV's iXML chunk (iXML 2.10 TRACK_LIST) names channel k after listener k, in order,
// with XML's special characters escaped. Reference: the chunk's text.
TEST(ChannelLayout, WavNamesItsChannelsInAnIxmlTrackList) {
  const test::TempFolder folder;
  const fs::path path = folder.path() / "named.wav";
  AudioWriteSettings settings;
  settings.channelNames = {"left", "right", "a <b> & 'c'"};
  writeAudio(path, ramps(3), settings);
  const std::optional<std::string> ixml = waveChunk(fileBytes(path), "iXML");
  ASSERT_TRUE(ixml.has_value());
  EXPECT_NE(ixml->find("<TRACK_COUNT>3</TRACK_COUNT>"), std::string::npos) << *ixml;
  const std::size_t left = ixml->find(
      "<CHANNEL_INDEX>1</CHANNEL_INDEX><INTERLEAVE_INDEX>1</INTERLEAVE_INDEX><NAME>left</NAME>");
  const std::size_t right = ixml->find(
      "<CHANNEL_INDEX>2</CHANNEL_INDEX><INTERLEAVE_INDEX>2</INTERLEAVE_INDEX><NAME>right</NAME>");
  const std::size_t third = ixml->find("<NAME>a &lt;b&gt; &amp; &apos;c&apos;</NAME>");
  EXPECT_NE(left, std::string::npos) << *ixml;
  EXPECT_NE(right, std::string::npos) << *ixml;
  EXPECT_NE(third, std::string::npos) << *ixml;
  EXPECT_LT(left, right);
  EXPECT_LT(right, third);
  AudioWriteSettings oneName;
  oneName.channelNames = {"one"};
  EXPECT_THROW(writeAudio(folder.path() / "wrong.wav", ramps(3), oneName), std::invalid_argument);
}

// Claim: a FLAC of 3 to 8 channels carries the Vorbis comment WAVEFORMATEXTENSIBLE_CHANNEL_MASK=0x0
// (the FLAC format's override of its default layouts for 3–8 channels: RFC 9639, Vorbis comment
// block, "channel mask"), and
// stays a FLAC that libsndfile decodes to the same samples as without it (24-bit: within
// 1.5 LSB of the input, the TPDF bound of audio_file_test.cpp). Mono and stereo get no mask.
TEST(ChannelLayout, FlacFromThreeChannelsOnSaysNoSpeakerPositions) {
  const test::TempFolder folder;
  for (std::size_t channels : {2u, 3u, 6u, 8u}) {
    const fs::path path = folder.path() / ("c" + std::to_string(channels) + ".flac");
    AudioWriteSettings settings;
    settings.format = AudioFormat::Flac;
    const AudioBuffer audio = ramps(channels);
    writeAudio(path, audio, settings);
    const std::vector<std::string> comments = flacComments(fileBytes(path));
    const auto masks =
        std::count(comments.begin(), comments.end(), "WAVEFORMATEXTENSIBLE_CHANNEL_MASK=0x0");
    EXPECT_EQ(masks, channels >= 3 ? 1 : 0) << channels << " channels";
    const AudioBuffer read = readAudio(path);
    ASSERT_EQ(read.channels.size(), channels);
    double largestError = 0;
    for (std::size_t c = 0; c < channels; ++c) {
      ASSERT_EQ(read.channels[c].size(), audio.channels[c].size());
      for (std::size_t i = 0; i < audio.channels[c].size(); ++i)
        largestError = std::max(largestError, std::abs(static_cast<double>(read.channels[c][i]) -
                                                       audio.channels[c][i]));
    }
    EXPECT_LE(largestError, 1.5 * std::ldexp(1.0, -23)) << channels << " channels";
  }
  for (const auto& entry : fs::directory_iterator(folder.path()))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
        << "left behind: " << entry.path();
}

}  // namespace
}  // namespace fluidsound::io
