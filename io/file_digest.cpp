// io/file_digest.cpp — see file_digest.h.
#include "io/file_digest.h"

#include <array>
#include <fstream>

namespace fluidsound::io {
namespace {

constexpr std::uint64_t kFnv1aPrime = 0x100000001b3ull;
/// Bytes read per piece: large enough that the read calls cost nothing next to the hash.
constexpr std::size_t kReadPieceBytes = 1u << 16;

}  // namespace

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash) {
  for (const unsigned char c : bytes) hash = (hash ^ c) * kFnv1aPrime;
  return hash;
}

std::optional<FileDigest> digestOfFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  FileDigest digest;
  std::array<char, kReadPieceBytes> piece;
  while (in) {
    in.read(piece.data(), static_cast<std::streamsize>(piece.size()));
    const auto count = static_cast<std::size_t>(in.gcount());
    digest.bytes += count;
    digest.fnv1a = fnv1a64(std::string_view(piece.data(), count), digest.fnv1a);
  }
  if (in.bad() || !in.eof()) return std::nullopt;
  return digest;
}

std::string hexDigits(std::uint64_t hash) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i, hash >>= 4) text[static_cast<std::size_t>(i)] = kDigits[hash & 0xf];
  return text;
}

std::optional<std::uint64_t> parseHexDigits(std::string_view text) {
  if (text.size() != 16) return std::nullopt;
  std::uint64_t value = 0;
  for (const char c : text) {
    int digit = -1;
    if (c >= '0' && c <= '9')
      digit = c - '0';
    else if (c >= 'a' && c <= 'f')
      digit = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F')
      digit = c - 'A' + 10;
    if (digit < 0) return std::nullopt;
    value = (value << 4) | static_cast<std::uint64_t>(digit);
  }
  return value;
}

}  // namespace fluidsound::io
