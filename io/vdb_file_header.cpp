// io/vdb_file_header.cpp — see vdb_file_header.h. The layout is OpenVDB's (io/Archive.cc,
// io/File.cc, io/GridDescriptor.cc, Metadata.cc of OpenVDB 10), all little-endian:
//   header:     int64 magic 0x56444220, uint32 file version, uint32 × 2 library version,
//               char has-grid-offsets, char[36] UUID
//   metadata:   int32 count, then per entry string name, string type, uint32 size, bytes
//   descriptors: int32 count, then per grid string name, string type, string instance parent,
//               int64 grid, block and end offsets (the next descriptor starts at the end offset)
//   grid:       at its grid offset, uint32 compression flags, then metadata as above
//   string:     uint32 length, then the bytes
#include "io/vdb_file_header.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "io/input_error.h"

namespace fluidsound::io {
namespace {

constexpr std::int64_t kMagic = 0x56444220;    // " BDV"
constexpr std::uint32_t kOldestVersion = 222;  // OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION
constexpr std::uint32_t kNewestVersion = 224;  // OPENVDB_FILE_VERSION_MULTIPASS_IO (OpenVDB 10)
constexpr std::size_t kUuidBytes = 36;

/// Reads the header's fields in order, each checked against the bytes left before `end`.
class HeaderReader {
 public:
  explicit HeaderReader(const std::filesystem::path& path)
      : name_(path.string()), in_(path, std::ios::binary) {
    if (!in_) throw InputError(name_, "", "a readable OpenVDB file", "cannot open it");
    in_.seekg(0, std::ios::end);
    size_ = static_cast<std::int64_t>(in_.tellg());
    end_ = size_;
    in_.seekg(0);
  }

  std::int64_t size() const { return size_; }
  std::int64_t position() { return static_cast<std::int64_t>(in_.tellg()); }
  void limitTo(std::int64_t end) { end_ = end; }
  void seek(std::int64_t offset) { in_.seekg(offset); }

  template <typename T>
  T number(const std::string& field) {
    requireBytes(field, sizeof(T));
    T value{};
    in_.read(reinterpret_cast<char*>(&value), sizeof(T));  // little-endian, as x86-64 and OpenVDB
    return value;
  }

  /// A length or count that must fit in the bytes left (at least `bytesEach` bytes per item).
  std::int64_t count(const std::string& field, std::int64_t bytesEach) {
    const std::int64_t value = number<std::int32_t>(field);
    const std::int64_t left = end_ - position();
    if (value < 0 || value * bytesEach > left)
      fail(field, "a count within the file (at most " + std::to_string(left / bytesEach) + " left)",
           std::to_string(value));
    return value;
  }

  void skip(const std::string& field, std::int64_t bytes) {
    requireBytes(field, bytes);
    in_.seekg(bytes, std::ios::cur);
  }

  /// A string: its uint32 length within the bytes left, then skipped over.
  void string(const std::string& field) {
    const std::int64_t length = number<std::uint32_t>(field);
    const std::int64_t left = end_ - position();
    if (length > left)
      fail(field, "a length within the file (at most " + std::to_string(left) + " bytes left)",
           std::to_string(length));
    in_.seekg(length, std::ios::cur);
  }

  [[noreturn]] void fail(const std::string& field, const std::string& expected,
                         const std::string& found) const {
    throw InputError(name_, field, expected, found);
  }

 private:
  void requireBytes(const std::string& field, std::int64_t bytes) {
    const std::int64_t left = end_ - position();
    if (!in_ || left < bytes)
      fail(field, std::to_string(bytes) + " more bytes",
           "the end of the header after " + std::to_string(position()));
  }

  std::string name_;
  std::ifstream in_;
  std::int64_t size_ = 0;
  std::int64_t end_ = 0;
};

/// A metadata block: int32 count, then name, type and sized value per entry.
void checkMetadata(HeaderReader& in, const std::string& field) {
  // Each entry holds at least two string lengths and a value size.
  const std::int64_t entries = in.count(field + " count", 12);
  for (std::int64_t i = 0; i < entries; ++i) {
    const std::string entry = field + "[" + std::to_string(i) + "]";
    in.string(entry + " name");
    in.string(entry + " type");
    in.string(entry + " value");  // uint32 size, then the bytes: the same shape as a string
  }
}

/// One grid descriptor and the metadata block at its grid offset; leaves `in` at the next one.
void checkGrid(HeaderReader& in, std::int64_t index) {
  const std::string grid = "grid " + std::to_string(index);
  in.string(grid + " name");
  in.string(grid + " type");
  in.string(grid + " instance parent");
  const std::int64_t descriptorEnd = in.position() + 24;
  const auto gridOffset = in.number<std::int64_t>(grid + " grid offset");
  const auto blockOffset = in.number<std::int64_t>(grid + " block offset");
  const auto endOffset = in.number<std::int64_t>(grid + " end offset");
  if (!(descriptorEnd <= gridOffset && gridOffset <= blockOffset && blockOffset <= endOffset &&
        endOffset <= in.size()))
    in.fail(grid + " offsets",
            "offsets in order within the file (" + std::to_string(descriptorEnd) +
                " <= grid <= block <= end <= " + std::to_string(in.size()) + ")",
            "grid " + std::to_string(gridOffset) + ", block " + std::to_string(blockOffset) +
                ", end " + std::to_string(endOffset));
  in.seek(gridOffset);
  in.limitTo(blockOffset);
  in.skip(grid + " compression", 4);
  checkMetadata(in, grid + " metadata");
  in.limitTo(in.size());
  in.seek(endOffset);
}

}  // namespace

void requireIntactVdbHeader(const std::filesystem::path& path) {
  HeaderReader in(path);
  if (in.number<std::int64_t>("magic number") != kMagic)
    in.fail("magic number", "an OpenVDB file", "another kind of file");
  const auto version = in.number<std::uint32_t>("file version");
  if (version < kOldestVersion || version > kNewestVersion)
    in.fail("file version",
            "an OpenVDB file format " + std::to_string(kOldestVersion) + " to " +
                std::to_string(kNewestVersion),
            std::to_string(version));
  in.skip("library version", 8);
  if (in.number<char>("grid offsets") != 1)
    in.fail("grid offsets", "a file with grid offsets (as openvdb::io::File writes)", "none");
  in.skip("UUID", kUuidBytes);
  checkMetadata(in, "metadata");
  const std::int64_t grids = in.count("grid count", 36);  // 3 string lengths, 3 offsets
  for (std::int64_t i = 0; i < grids; ++i) checkGrid(in, i);
}

}  // namespace fluidsound::io
