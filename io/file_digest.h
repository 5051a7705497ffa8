// io/file_digest.h — what identifies a file's contents for `run`'s resume check: its size and a
// 64-bit FNV-1a hash of its bytes (Fowler, Noll & Vo; offset basis 0xcbf29ce484222325, prime
// 0x100000001b3). Not a cryptographic hash: it detects truncation, edits and replacement by
// another run's output, not tampering.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace fluidsound::io {

/// FNV-1a 64 offset basis: the hash of no bytes.
inline constexpr std::uint64_t kFnv1aOffsetBasis = 0xcbf29ce484222325ull;

/// @brief FNV-1a 64 of `bytes`, continuing from `hash` (so a hash over several pieces equals the
///        hash of their concatenation).
std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash = kFnv1aOffsetBasis);

/// A file's size and the FNV-1a 64 of its bytes.
struct FileDigest {
  std::uintmax_t bytes = 0;
  std::uint64_t fnv1a = kFnv1aOffsetBasis;
  bool operator==(const FileDigest&) const = default;
};

/// @brief The digest of the regular file at `path` (a symbolic link is followed), read in pieces.
/// @return none if `path` is missing, not a regular file or cannot be read to its end
std::optional<FileDigest> digestOfFile(const std::filesystem::path& path);

/// `hash` as 16 lower-case hex digits, the form stages.json stores.
std::string hexDigits(std::uint64_t hash);

/// @brief The value of 16 hex digits (either case); none for any other text.
std::optional<std::uint64_t> parseHexDigits(std::string_view text);

}  // namespace fluidsound::io
