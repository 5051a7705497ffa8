// io/channel_layout.cpp — speaker masks and channel names in written WAV/FLAC (see
// channel_layout.h). Byte layouts: WAVE_FORMAT_EXTENSIBLE (Microsoft, "Multiple channel audio
// data and WAVE files", 2017), FLAC metadata blocks (RFC 9639) and Vorbis comments (Xiph,
// "Ogg Vorbis I specification" §5).
#include "io/channel_layout.h"

#include <cstdint>
#include <cstring>
#include <string_view>

#include "io/input_error.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

constexpr std::uint16_t kWaveFormatExtensible = 0xFFFE;
/// Offsets inside the `fmt ` chunk's data: cbSize, and dwChannelMask after wValidBitsPerSample.
constexpr std::size_t kCbSizeOffset = 16, kChannelMaskOffset = 20, kExtensibleFmtBytes = 40;
constexpr std::uint8_t kFlacVorbisCommentType = 4, kFlacLastBlockFlag = 0x80;
constexpr std::string_view kNoSpeakerMask = "WAVEFORMATEXTENSIBLE_CHANNEL_MASK=0x0";
constexpr std::string_view kMaskKey = "WAVEFORMATEXTENSIBLE_CHANNEL_MASK=";

[[noreturn]] void cannotLabel(const fs::path& path, const std::string& reason) {
  throw OutputError(path.string() + ": cannot write: " + reason);
}

std::uint32_t littleEndian32(const unsigned char* bytes) {
  return static_cast<std::uint32_t>(bytes[0]) | (static_cast<std::uint32_t>(bytes[1]) << 8) |
         (static_cast<std::uint32_t>(bytes[2]) << 16) |
         (static_cast<std::uint32_t>(bytes[3]) << 24);
}

void appendLittleEndian32(std::string& out, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8)
    out.push_back(static_cast<char>((value >> shift) & 0xff));
}

std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// The comments of a Vorbis comment block's body other than a channel mask, and its vendor.
struct VorbisComments {
  std::string vendor = "fluidsound";
  std::vector<std::string> entries;
};

VorbisComments parseVorbisComments(const fs::path& path, const std::string& body) {
  VorbisComments comments;
  const auto* bytes = reinterpret_cast<const unsigned char*>(body.data());
  std::size_t at = 0;
  const auto field = [&]() -> std::string {
    if (at + 4 > body.size()) cannotLabel(path, "its Vorbis comment block is truncated");
    const std::uint32_t length = littleEndian32(bytes + at);
    at += 4;
    if (length > body.size() - at) cannotLabel(path, "its Vorbis comment block is truncated");
    std::string text = body.substr(at, length);
    at += length;
    return text;
  };
  comments.vendor = field();
  if (at + 4 > body.size()) cannotLabel(path, "its Vorbis comment block is truncated");
  const std::uint32_t count = littleEndian32(bytes + at);
  at += 4;
  for (std::uint32_t i = 0; i < count; ++i) {
    std::string entry = field();
    if (!entry.starts_with(kMaskKey)) comments.entries.push_back(std::move(entry));
  }
  return comments;
}

std::string vorbisCommentBody(const VorbisComments& comments) {
  std::string body;
  appendLittleEndian32(body, static_cast<std::uint32_t>(comments.vendor.size()));
  body += comments.vendor;
  appendLittleEndian32(body, static_cast<std::uint32_t>(comments.entries.size()));
  for (const std::string& entry : comments.entries) {
    appendLittleEndian32(body, static_cast<std::uint32_t>(entry.size()));
    body += entry;
  }
  return body;
}

struct FlacBlock {
  std::uint8_t type = 0;
  std::string body;
};

/// Reads "fLaC" and every metadata block of an encoded stream, in place.
/// @return the blocks; `audioStart` is set to the offset of the first audio frame
std::vector<FlacBlock> readFlacMetadata(const fs::path& path, std::string_view flac,
                                        std::size_t& audioStart) {
  if (flac.size() < 4 || flac.substr(0, 4) != "fLaC")
    cannotLabel(path, "the encoder did not write a FLAC stream");
  std::vector<FlacBlock> blocks;
  std::size_t at = 4;
  bool last = false;
  while (!last) {
    if (flac.size() - at < 4) cannotLabel(path, "its FLAC metadata is truncated");
    const auto* header = reinterpret_cast<const unsigned char*>(flac.data() + at);
    last = (header[0] & kFlacLastBlockFlag) != 0;
    const std::size_t length =
        (std::size_t{header[1]} << 16) | (std::size_t{header[2]} << 8) | header[3];
    at += 4;
    if (flac.size() - at < length) cannotLabel(path, "its FLAC metadata is truncated");
    blocks.push_back(
        {static_cast<std::uint8_t>(header[0] & 0x7f), std::string(flac.substr(at, length))});
    at += length;
  }
  audioStart = at;
  return blocks;
}

void appendFlacBlock(std::string& out, const FlacBlock& block, bool last) {
  const std::size_t length = block.body.size();
  out.push_back(static_cast<char>(block.type | (last ? kFlacLastBlockFlag : 0)));
  out.push_back(static_cast<char>((length >> 16) & 0xff));
  out.push_back(static_cast<char>((length >> 8) & 0xff));
  out.push_back(static_cast<char>(length & 0xff));
  out += block.body;
}

}  // namespace

std::string ixmlTrackList(const std::vector<std::string>& names) {
  std::string xml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<BWFXML>\n<IXML_VERSION>2.10</IXML_VERSION>\n";
  xml += "<TRACK_LIST>\n<TRACK_COUNT>" + std::to_string(names.size()) + "</TRACK_COUNT>\n";
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string index = std::to_string(k + 1);
    xml += "<TRACK><CHANNEL_INDEX>" + index + "</CHANNEL_INDEX><INTERLEAVE_INDEX>" + index +
           "</INTERLEAVE_INDEX><NAME>" + xmlEscaped(names[k]) + "</NAME></TRACK>\n";
  }
  return xml + "</TRACK_LIST>\n</BWFXML>\n";
}

void clearWaveSpeakerMask(std::string& wav, const fs::path& name) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(wav.data());
  if (wav.size() < 12 || std::memcmp(bytes, "RIFF", 4) != 0 ||
      std::memcmp(bytes + 8, "WAVE", 4) != 0)
    cannotLabel(name, "the encoder did not write a RIFF WAVE file");
  for (std::size_t at = 12; at + 8 <= wav.size();) {
    const std::size_t size = littleEndian32(bytes + at + 4);
    if (std::memcmp(bytes + at, "fmt ", 4) != 0) {
      at += 8 + size + (size & 1u);
      continue;
    }
    const unsigned char* fmt = bytes + at + 8;
    if (size < kExtensibleFmtBytes || at + 8 + kExtensibleFmtBytes > wav.size())
      cannotLabel(name, "its fmt chunk is not WAVE_FORMAT_EXTENSIBLE");
    const auto tag = static_cast<std::uint16_t>(fmt[0] | (fmt[1] << 8));
    const auto cbSize =
        static_cast<std::uint16_t>(fmt[kCbSizeOffset] | (fmt[kCbSizeOffset + 1] << 8));
    if (tag != kWaveFormatExtensible || cbSize < 22)
      cannotLabel(name, "its fmt chunk is not WAVE_FORMAT_EXTENSIBLE");
    wav.replace(at + 8 + kChannelMaskOffset, 4, 4, '\0');
    return;
  }
  cannotLabel(name, "the encoder wrote no fmt chunk");
}

void clearFlacSpeakerMask(std::string& flac, const fs::path& name) {
  std::size_t audioStart = 0;
  std::vector<FlacBlock> blocks = readFlacMetadata(name, flac, audioStart);
  VorbisComments comments;
  std::vector<FlacBlock> kept;
  for (FlacBlock& block : blocks) {
    if (block.type == kFlacVorbisCommentType)
      comments = parseVorbisComments(name, block.body);
    else
      kept.push_back(std::move(block));
  }
  comments.entries.emplace_back(kNoSpeakerMask);
  std::string metadata = "fLaC";
  for (const FlacBlock& block : kept) appendFlacBlock(metadata, block, false);
  appendFlacBlock(metadata, {kFlacVorbisCommentType, vorbisCommentBody(comments)}, true);
  flac.replace(0, audioStart, metadata);  // the audio frames are moved, never copied
}

}  // namespace fluidsound::io
