// io/vdb_header_check.cpp — see vdb_header_check.h.
#include "io/vdb_header_check.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "io/input_error.h"

namespace fluidsound::io {
namespace {

/// OpenVDB's magic number, the first 8 bytes of a file ("  BDV" little-endian, then zeros).
constexpr std::int64_t kVdbMagic = 0x56444220;
/// File format versions this check knows: 222 (node-mask compression) to 224 (OpenVDB 10).
constexpr std::uint32_t kMinVersion = 222, kMaxVersion = 224;
/// Longest string whose text the check keeps (type names); longer ones are only skipped.
constexpr std::uint32_t kShortString = 64;
/// The type name of OpenVDB's delayed-load metadata, whose value starts with a node count.
constexpr const char* kDelayedLoadType = "__delayedload";
/// Length of the UUID text after the library version and the offsets flag.
constexpr std::uint64_t kUuidBytes = 36;

/// A bounds-checked little-endian reader over the file's bytes (OpenVDB writes host order; the
/// frames are written and read on little-endian machines).
class HeaderReader {
 public:
  HeaderReader(std::ifstream& in, std::uint64_t size, const std::string& file)
      : in_(in), size_(size), file_(file) {}

  [[noreturn]] void fail(const std::string& expected, const std::string& found) const {
    throw InputError(file_, "byte " + std::to_string(at_), expected, found);
  }
  std::uint64_t at() const { return at_; }

  template <class T>
  T value(const char* what) {
    if (size_ - at_ < sizeof(T))
      fail(std::string("a VDB file with its ") + what, "the end of the file (truncated)");
    T v{};
    in_.seekg(static_cast<std::streamoff>(at_));
    in_.read(reinterpret_cast<char*>(&v), sizeof(T));
    if (!in_) fail(std::string("a readable ") + what, "a read error");
    at_ += sizeof(T);
    return v;
  }
  /// Skips `count` bytes that must be inside the file.
  void skip(std::uint64_t count, const char* what) {
    if (size_ - at_ < count)
      fail(std::string("a VDB file with its ") + what + " (" + std::to_string(count) + " bytes)",
           std::to_string(size_ - at_) + " bytes left (damaged or truncated)");
    at_ += count;
  }
  /// A length-prefixed string (uint32 length, then its bytes), skipped; returns its text when it
  /// is short (a type name), else "".
  std::string string(const char* what) {
    const std::uint32_t length = value<std::uint32_t>(what);
    const std::uint64_t start = at_;
    skip(length, what);
    std::string text;
    if (length <= kShortString) {
      text.resize(length);
      in_.seekg(static_cast<std::streamoff>(start));
      in_.read(text.data(), length);
    }
    return text;
  }
  /// Metadata: an int32 count, then per entry its name, type name and uint32-sized value.
  void metadata(const char* what) {
    const std::int32_t count = value<std::int32_t>(what);
    if (count < 0 || static_cast<std::uint64_t>(count) > size_ - at_)
      fail(std::string("a count of ") + what, std::to_string(count));
    for (std::int32_t k = 0; k < count; ++k) {
      string("metadata name");
      const std::string type = string("metadata type name");
      const std::uint32_t bytes = value<std::uint32_t>("metadata value size");
      const std::uint64_t end = at_ + bytes;
      if (type == kDelayedLoadType && bytes >= sizeof(std::uint32_t)) {
        // OpenVDB sizes two arrays (1 + 8 bytes per node) by this count before reading them:
        // a node takes at least a byte of the file, so a larger count is damage.
        const std::uint32_t nodes = value<std::uint32_t>("delayed-load node count");
        if (nodes > size_)
          fail("a delayed-load node count of at most the file's size", std::to_string(nodes));
        at_ -= sizeof(std::uint32_t);
      }
      skip(end - at_, "metadata value");
    }
  }
  /// Moves to `offset`, which must be inside the file and not before where we are.
  void seek(std::int64_t offset, const char* what) {
    if (offset < 0 || static_cast<std::uint64_t>(offset) < at_ ||
        static_cast<std::uint64_t>(offset) > size_)
      fail(std::string("a ") + what + " within the file (" + std::to_string(size_) + " bytes)",
           std::to_string(offset));
    at_ = static_cast<std::uint64_t>(offset);
  }

 private:
  std::ifstream& in_;
  std::uint64_t size_;
  std::uint64_t at_ = 0;
  const std::string& file_;
};

}  // namespace

void requireIntactVdbHeader(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in)
    throw InputError(file, "", "a readable frame file", ec ? ec.message() : "cannot open it");
  HeaderReader r(in, size, file);
  if (r.value<std::int64_t>("magic number") != kVdbMagic) {
    throw InputError(file, "", "an OpenVDB file (magic number 0x56444220)", "another kind of file");
  }
  const std::uint32_t version = r.value<std::uint32_t>("format version");
  if (version < kMinVersion || version > kMaxVersion)
    r.fail("a VDB file format from 222 to 224 (as fluidsound writes)", std::to_string(version));
  r.skip(8, "library version");
  if (r.value<std::uint8_t>("grid offsets flag") != 1)
    r.fail("a VDB file with grid offsets", "none");
  r.skip(kUuidBytes, "UUID");
  r.metadata("file metadata");
  const std::int32_t grids = r.value<std::int32_t>("grid count");
  if (grids < 0 || grids > 1024) r.fail("a grid count from 0 to 1024", std::to_string(grids));
  for (std::int32_t g = 0; g < grids; ++g) {
    r.string("grid name");
    r.string("grid type name");
    r.string("instance parent name");
    const std::int64_t gridPos = r.value<std::int64_t>("grid offset");
    const std::int64_t blockPos = r.value<std::int64_t>("block offset");
    const std::int64_t endPos = r.value<std::int64_t>("end offset");
    r.seek(gridPos, "grid offset");
    r.value<std::uint32_t>("grid compression flags");
    r.metadata("grid metadata");
    r.string("transform type name");
    r.seek(blockPos, "block offset");
    r.seek(endPos, "end offset");
  }
}

}  // namespace fluidsound::io
