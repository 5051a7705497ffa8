// io/vdb_file_check.cpp — see vdb_file_check.h. The layout is OpenVDB's (io/Archive.cc,
// io/File.cc, io/GridDescriptor.cc, Metadata.cc of OpenVDB 10), all little-endian:
//   header:     int64 magic 0x56444220, uint32 file version, uint32 × 2 library version,
//               char has-grid-offsets, char[36] UUID
//   metadata:   int32 count, then per entry string name, string type, uint32 size, bytes
//   descriptors: int32 count, then per grid string name, string type, string instance parent,
//               int64 grid, block and end offsets (the next descriptor starts at the end offset)
//   grid:       at its grid offset, uint32 compression flags, metadata as above, the transform
//   string:     uint32 length, then the bytes
// A metadata value of a registered fixed-size type (Metadata.h, TypedMetadata<T>::readValue)
// is read as sizeof(T) bytes whatever its size says, so its size must be that; one of type
// `__delayedload` (io/DelayedLoadMetadata.cc, readValue) holds
//   uint32 node count, then the nodes' masks (int8 each) and compressed sizes (int64 each; a size
//   of 0xffffffff: none), each array as a uint32 size and that many bytes of blosc (a 16-byte
//   header: version, flags, uint32 uncompressed, block and compressed sizes), or size 0 and the
//   raw array
// and OpenVDB allocates what the count, the sizes and the blosc header say before reading them.
// For every float and Vec3 grid (a FloatTree or Vec3STree 5-4-3: the `surface` FrameSurface reads,
// a cache's `velocity`), after its transform (io/Archive.cc, math/Transform.cc, tree/RootNode.h,
// InternalNode.h, LeafNode.h, io/Compression.h); a value is 4 or 12 bytes, and in the compressed
// value arrays 2 or 6 when the grid is saved as half floats (its type ends "_HalfFloat" and its
// metadata says is_saved_as_half_float; an array of no values is then not written at all):
//   transform:  string map type, then the map's fixed-size values
//   topology:   int32 buffer count, a value (background), uint32 tile and child counts, tiles
//               (int32 × 3 origin, a value, bool), children (int32 × 3 origin, internal node 5)
//   internal N: child mask, value mask (2^(3N) bits each), compressed values, then each child
//   leaf:       value mask (512 bits); its values come after the topology, at the block offset,
//               leaf by leaf (root children in origin order): value mask again, compressed values
//   compressed values: int8 kind, 0–2 values, maybe a selection mask, then the data: with blosc
//               or zip an int64 size (≤ 0: that many raw bytes, negated), else raw values
#include "io/vdb_file_check.h"

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "io/input_error.h"

namespace fluidsound::io {
namespace {

constexpr std::int64_t kMagic = 0x56444220;    // " BDV"
constexpr std::uint32_t kOldestVersion = 222;  // OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION
constexpr std::uint32_t kNewestVersion = 224;  // OPENVDB_FILE_VERSION_MULTIPASS_IO (OpenVDB 10)
constexpr std::size_t kUuidBytes = 36;
constexpr std::int64_t kMaxGrids = 1024;  // more than any frame holds: damage

/// Reads the header's fields in order, each checked against the bytes left before `end`.
class HeaderReader {
 public:
  explicit HeaderReader(const std::filesystem::path& path)
      : name_(path.string()), in_(path, std::ios::binary) {
    std::error_code error;
    size_ = static_cast<std::int64_t>(std::filesystem::file_size(path, error));
    if (error || !in_)
      throw InputError(name_, "", "a readable OpenVDB file",
                       error ? error.message() : "cannot open it");
    end_ = size_;
  }

  std::int64_t size() const { return size_; }
  std::int64_t position() { return static_cast<std::int64_t>(in_.tellg()); }
  /// The end of the part being read (the file, a grid's header or a metadata value).
  std::int64_t end() const { return end_; }
  std::int64_t left() { return end_ - position(); }
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

  /// `bytes` raw bytes into `out`.
  void bytes(const std::string& field, char* out, std::int64_t bytes) {
    requireBytes(field, bytes);
    in_.read(out, bytes);
  }

  void skip(const std::string& field, std::int64_t bytes) {
    requireBytes(field, bytes);
    in_.seekg(bytes, std::ios::cur);
  }

  /// A string: its uint32 length within the bytes left, then the text (kept only up to 64 bytes:
  /// the names the check compares).
  std::string string(const std::string& field) {
    const std::int64_t length = number<std::uint32_t>(field);
    const std::int64_t left = end_ - position();
    if (length > left)
      fail(field, "a length within the file (at most " + std::to_string(left) + " bytes left)",
           std::to_string(length));
    if (length > 64) {
      in_.seekg(length, std::ios::cur);
      return {};
    }
    std::string text(static_cast<std::size_t>(length), '\0');
    in_.read(text.data(), length);
    return text;
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
           "the end of its part of the file at byte " + std::to_string(end_) +
               " (damaged or truncated)");
  }

  std::string name_;
  std::ifstream in_;
  std::int64_t size_ = 0;
  std::int64_t end_ = 0;
};

/// The bytes OpenVDB reads for a value of a registered fixed-size metadata type (openvdb.h
/// MetaTypes, and the point index types openvdb::initialize adds), or -1 for any other type.
std::int64_t fixedValueBytes(const std::string& type) {
  static const std::map<std::string, std::int64_t> bytes{
      {"bool", 1},    {"float", 4},   {"double", 8},  {"int32", 4},       {"int64", 8},
      {"vec2i", 8},   {"vec2s", 8},   {"vec2d", 16},  {"vec3i", 12},      {"vec3s", 12},
      {"vec3d", 24},  {"vec4i", 16},  {"vec4s", 16},  {"vec4d", 32},      {"mat4s", 64},
      {"mat4d", 128}, {"ptidx32", 4}, {"ptidx64", 8}, {"ptdataidx32", 4}, {"ptdataidx64", 8}};
  const auto found = bytes.find(type);
  return found == bytes.end() ? -1 : found->second;
}

constexpr std::int64_t kBloscHeaderBytes = 16;  // BLOSC_MIN_HEADER_LENGTH
constexpr std::int64_t kBloscPadBytes = 128;    // io/StreamCompression.h BLOSC_PAD_BYTES

/// One array of a delayed-load value: `nodes` items of `bytesEach` bytes, as a uint32 size and
/// that many blosc bytes, or size 0 and the raw items (or, when `optional`, size 0xffffffff and
/// nothing). OpenVDB allocates the size, and the blosc header's uncompressed size, unchecked;
/// blosc trusts the header's block and compressed sizes.
void checkDelayedLoadArray(HeaderReader& in, const std::string& field, std::int64_t nodes,
                           std::int64_t bytesEach, bool optional) {
  const std::int64_t size = in.number<std::uint32_t>(field + " size");
  if (optional && size == 0xffffffff) return;
  const std::int64_t raw = nodes * bytesEach;
  if (size == 0) return in.skip(field, raw);
  const std::int64_t left = in.left();
  if (size < kBloscHeaderBytes || size > left)
    in.fail(field + " size",
            "0 (raw) or a blosc block of 16 to " + std::to_string(left) +
                " bytes (what is left of the value)",
            std::to_string(size));
  std::array<std::uint32_t, 4> header{};  // version and flags, uncompressed, block, compressed
  in.bytes(field + " blosc header", reinterpret_cast<char*>(header.data()), kBloscHeaderBytes);
  const std::int64_t uncompressed = header[1], block = header[2], compressed = header[3];
  // io::bloscDecompress accepts the nodes' size or, for 128 bytes or fewer, the padded 128.
  if (uncompressed != raw && !(uncompressed == kBloscPadBytes && raw <= kBloscPadBytes))
    in.fail(field + " uncompressed size",
            "the size of " + std::to_string(nodes) + " nodes (" + std::to_string(raw) + " bytes)",
            std::to_string(uncompressed));
  if (block > uncompressed)
    in.fail(field + " block size",
            "at most the uncompressed size (" + std::to_string(uncompressed) + " bytes)",
            std::to_string(block));
  if (compressed < kBloscHeaderBytes || compressed > size)
    in.fail(field + " compressed size",
            "16 to " + std::to_string(size) + " bytes (the block's size)",
            std::to_string(compressed));
  in.skip(field + " data", size - kBloscHeaderBytes);
}

/// A `__delayedload` value (io::DelayedLoadMetadata): the node count, the masks, the compressed
/// sizes, all within the value (`in` limited to it).
void checkDelayedLoad(HeaderReader& in, const std::string& field) {
  const std::int64_t nodes = in.number<std::uint32_t>(field + " node count");
  // OpenVDB sizes both arrays (1 + 8 bytes per node) by it: a node takes at least a byte of
  // the file, so a larger count is damage.
  if (nodes > in.size())
    in.fail(
        field + " node count",
        "a delayed-load node count of at most the file's size (" + std::to_string(in.size()) + ")",
        std::to_string(nodes));
  checkDelayedLoadArray(in, field + " masks", nodes, 1, false);
  checkDelayedLoadArray(in, field + " compressed sizes", nodes, 8, true);
}

/// One metadata entry's value: a uint32 size within the part read, then the bytes, which must
/// be what OpenVDB will read for the entry's type.
/// @return the value when it is a bool (1 byte), else false
bool checkMetadataValue(HeaderReader& in, const std::string& field, const std::string& type) {
  const std::int64_t size = in.number<std::uint32_t>(field + " size");
  const std::int64_t left = in.left();
  if (size > left)
    in.fail(field + " size",
            "a length within the file (at most " + std::to_string(left) + " bytes left)",
            std::to_string(size));
  const std::int64_t fixed = fixedValueBytes(type);
  if (fixed >= 0 && size != fixed)
    in.fail(field + " size", std::to_string(fixed) + " bytes (the size of type " + type + ")",
            std::to_string(size));
  const std::int64_t valueEnd = in.position() + size;
  bool value = false;
  if (type == "__delayedload" && size > 0) {  // OpenVDB reads nothing for an empty one
    const std::int64_t partEnd = in.end();
    in.limitTo(valueEnd);
    checkDelayedLoad(in, field);
    in.limitTo(partEnd);
  } else if (type == "bool") {
    value = in.number<char>(field) != 0;
  }
  in.seek(valueEnd);
  return value;
}

/// A metadata block: int32 count, then name, type and sized value per entry.
/// @return whether it says `is_saved_as_half_float` true (a grid's values stored as 16-bit
///         halves: Grid::readBuffers, io::getHalfFloat)
bool checkMetadata(HeaderReader& in, const std::string& field) {
  // Each entry holds at least two string lengths and a value size.
  const std::int64_t entries = in.count(field + " count", 12);
  bool half = false;
  for (std::int64_t i = 0; i < entries; ++i) {
    const std::string entry = field + "[" + std::to_string(i) + "]";
    const std::string name = in.string(entry + " name");
    const std::string type = in.string(entry + " type");
    const bool value = checkMetadataValue(in, entry + " value", type);
    if (name == "is_saved_as_half_float" && type == "bool") half = value;
  }
  return half;
}

constexpr std::uint32_t kZip = 1, kActiveMask = 2, kBlosc = 4;  // io::COMPRESS_*
constexpr std::int8_t kAllValues = 6;                           // io::NO_MASK_AND_ALL_VALS

/// A node mask of `bits` bits, read from the file.
using NodeMask = std::vector<std::uint64_t>;

NodeMask readMask(HeaderReader& in, const std::string& field, std::int64_t bits) {
  NodeMask mask(static_cast<std::size_t>(bits / 64));
  in.bytes(field, reinterpret_cast<char*>(mask.data()), bits / 8);
  return mask;
}

std::int64_t countOn(const NodeMask& mask) {
  std::int64_t count = 0;
  for (const std::uint64_t word : mask) count += std::popcount(word);
  return count;
}

/// How a tree's values are stored: a value's bytes in memory (the background, tiles and inactive
/// values are written so) and in the value arrays (half that when saved as half floats).
struct ValueLayout {
  std::int64_t valueBytes = 4;
  std::int64_t storedBytes = 4;
};

/// io::readCompressedValues: `values` per node, `mask` the node's value mask.
void checkValues(HeaderReader& in, const std::string& field, std::uint32_t compression,
                 std::int64_t values, const NodeMask& mask, const ValueLayout& layout) {
  const auto kind = in.number<std::int8_t>(field + " kind");
  if (kind == 2 || kind == 4 || kind == 5)
    in.skip(field + " inactive value", (kind == 5 ? 2 : 1) * layout.valueBytes);
  if (kind == 3 || kind == 4 || kind == 5) in.skip(field + " selection mask", values / 8);
  const std::int64_t count =
      (compression & kActiveMask) && kind != kAllValues ? countOn(mask) : values;
  const std::int64_t bytes = count * layout.storedBytes;
  // Half floats: nothing at all for no values, not even a size (io::HalfWriter/HalfReader return
  // early for a count below 1).
  if (layout.storedBytes != layout.valueBytes && count == 0) return;
  if (!(compression & (kZip | kBlosc))) return in.skip(field + " data", bytes);
  const auto size = in.number<std::int64_t>(field + " size");
  if (size <= 0 && size != -bytes)
    in.fail(field + " size",
            "a compressed size > 0 or minus the raw size (" + std::to_string(bytes) + " bytes)",
            std::to_string(size));
  in.skip(field + " data", size <= 0 ? bytes : size);
}

/// An internal node of log2 size `log2Dim` (5 or 4) and everything below it; the leaves' value
/// masks are appended to `leaves` in the order their values follow the topology.
void checkInternalNode(HeaderReader& in, const std::string& field, std::uint32_t compression,
                       const ValueLayout& layout, int log2Dim, std::vector<NodeMask>& leaves) {
  const std::int64_t values = std::int64_t{1} << (3 * log2Dim);
  const NodeMask children = readMask(in, field + " child mask", values);
  const NodeMask active = readMask(in, field + " value mask", values);
  checkValues(in, field + " values", compression, values, active, layout);
  for (std::size_t word = 0; word < children.size(); ++word)
    for (std::uint64_t bits = children[word]; bits != 0; bits &= bits - 1) {
      if (log2Dim == 4) {
        leaves.push_back(readMask(in, field + " leaf mask", 512));
      } else {
        checkInternalNode(in, field, compression, layout, log2Dim - 1, leaves);
      }
    }
}

/// The bytes of map types a transform may hold (math/Maps.h: each one's read()).
std::int64_t mapBytes(const std::string& type) {
  if (type == "UniformScaleTranslateMap" || type == "ScaleTranslateMap") return 6 * 24;
  if (type == "UniformScaleMap" || type == "ScaleMap") return 5 * 24;
  if (type == "TranslationMap") return 24;
  if (type == "AffineMap" || type == "UnitaryMap") return 128;
  return -1;
}

/// The transform's values, topology and leaf values of a float or Vec3 grid, after its
/// transform's map type `map`.
void checkTree(HeaderReader& in, const std::string& grid, const std::string& map, std::uint32_t compression,
               const ValueLayout& layout, std::int64_t blockOffset, std::int64_t endOffset) {
  const std::int64_t bytes = mapBytes(map);
  if (bytes < 0)
    in.fail(grid + " transform", "a scale, translation or affine map", "'" + map + "'");
  in.skip(grid + " transform", bytes);
  in.skip(grid + " buffer count", 4);
  in.skip(grid + " background", layout.valueBytes);
  const auto tiles = in.number<std::uint32_t>(grid + " tile count");
  const auto children = in.number<std::uint32_t>(grid + " child count");
  // A tile: its origin (3 int32), its value, its active flag.
  if (tiles > 0) in.skip(grid + " tiles", std::int64_t{tiles} * (12 + layout.valueBytes + 1));
  // Root children are kept by origin (a later one replaces an earlier one at the same origin),
  // and their leaves' values follow in origin order.
  std::map<std::tuple<std::int32_t, std::int32_t, std::int32_t>, std::vector<NodeMask>> roots;
  for (std::uint32_t i = 0; i < children; ++i) {
    const std::string child = grid + " root child " + std::to_string(i);
    std::array<std::int32_t, 3> origin{};
    in.bytes(child + " origin", reinterpret_cast<char*>(origin.data()), 12);
    std::vector<NodeMask> leaves;
    checkInternalNode(in, child, compression, layout, 5, leaves);
    roots[{origin[0], origin[1], origin[2]}] = std::move(leaves);
  }
  // OpenVDB reads the leaves' values right after the topology (io::Archive::readGrid), not at
  // the descriptor's block offset: the two must agree, or the values checked would not be those
  // read (a fuzzed file put its block offset 96 bytes past the topology's end, and OpenVDB
  // allocated a 0x7f…-byte blosc buffer from the bytes between).
  if (in.position() != blockOffset)
    in.fail(grid + " block offset", "the end of the grid's topology (" + std::to_string(in.position()) + ")",
            std::to_string(blockOffset));
  in.limitTo(endOffset);
  std::int64_t index = 0;
  for (const auto& [origin, leaves] : roots)
    for (const NodeMask& mask : leaves) {
      const std::string leaf = grid + " leaf " + std::to_string(index++);
      if (readMask(in, leaf + " value mask", 512) != mask)
        in.fail(leaf + " value mask", "the mask of the topology", "another");
      checkValues(in, leaf + " values", compression, 512, mask, layout);
    }
}

/// One grid descriptor, and the metadata block and transform type at its grid offset (for a float
/// or Vec3 grid, its whole tree); leaves `in` at the next descriptor.
void checkGrid(HeaderReader& in, std::int64_t index) {
  const std::string grid = "grid " + std::to_string(index);
  const std::string name = in.string(grid + " name");
  const std::string writtenType = in.string(grid + " type");
  const std::string parent = in.string(grid + " instance parent");
  // A grid saved as half floats has "_HalfFloat" after its type (io::GridDescriptor).
  const std::string halfSuffix = "_HalfFloat";
  const bool halfType = writtenType.size() > halfSuffix.size() &&
                        writtenType.compare(writtenType.size() - halfSuffix.size(), halfSuffix.size(), halfSuffix) == 0;
  const std::string type = halfType ? writtenType.substr(0, writtenType.size() - halfSuffix.size()) : writtenType;
  // io::File::readGrid("surface") reads the grid of that name (a unique name adds "\x03" and
  // an index to it).
  const bool surface = name.substr(0, name.find('\x03')) == "surface";
  if (surface && (type != "Tree_float_5_4_3" || !parent.empty()))
    in.fail(grid + " type", "a FloatGrid (Tree_float_5_4_3, not an instance)", "'" + writtenType + "'");
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
  const auto compression = in.number<std::uint32_t>(grid + " compression");
  const bool half = checkMetadata(in, grid + " metadata") || halfType;
  const std::string map = in.string(grid + " transform");  // every grid has one, instances too
  // The trees of float and Vec3 grids (a level set, a velocity), each value 4 or 12 bytes, 2 or 6
  // when saved as half floats; an instance shares its parent's tree and has none of its own.
  const std::int64_t valueBytes = type == "Tree_float_5_4_3" ? 4 : type == "Tree_vec3s_5_4_3" ? 12 : 0;
  if (valueBytes > 0 && parent.empty())
    checkTree(in, grid, map, compression, {valueBytes, half ? valueBytes / 2 : valueBytes}, blockOffset, endOffset);
  in.limitTo(in.size());
  in.seek(endOffset);
}

}  // namespace

void requireIntactVdbFile(const std::filesystem::path& path) {
  HeaderReader in(path);
  if (in.number<std::int64_t>("magic number") != kMagic)
    in.fail("magic number", "an OpenVDB file (magic number 0x56444220)", "another kind of file");
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
  if (grids > kMaxGrids)
    in.fail("grid count", "a grid count from 0 to " + std::to_string(kMaxGrids),
            std::to_string(grids));
  for (std::int64_t i = 0; i < grids; ++i) checkGrid(in, i);
}

}  // namespace fluidsound::io
