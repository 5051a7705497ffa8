// Tests of io/vdb_file_check.h: a corrupt .vdb file is refused with a one-line InputError
// naming the file and the part of it, before OpenVDB allocates what its lengths say (cases found
// by tests/fuzz/frame_vdb_fuzz; their inputs are in tests/fuzz/corpus/frame_vdb/), and the
// reader (io/frame_surface.h) that calls the check first turns any damage into an InputError.
#include "sim/scene.h"
#include "io/vdb_file_check.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "io/frame_files.h"
#include "io/frame_surface.h"
#include "io/input_error.h"
#include "sim/fluid/fluid_solver.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

// The layout of a frame written by writeFrameVdb (OpenVDB 10, file format 224): the first grid
// descriptor starts after the 57-byte header, the file metadata (fps, frame, time, units, up_axis)
// and the grid count (4), with the length of its name "surface": found, not counted.
std::size_t firstDescriptor(const std::string& bytes) {
  const std::size_t at = bytes.find(std::string("\x07\0\0\0surface", 11));
  EXPECT_NE(at, std::string::npos);
  return at;
}

/// The bytes of frames/0000.vdb of a resting layer half the height of a box `cells` cells of
/// 1 cm wide (4: 8 leaves in the grid; 10: enough for blosc to compress the delayed-load table).
std::string frameBytes(const test::TempFolder& folder, int cells = 4) {
  const double side = 0.01 * cells;  // [m]
  sim::Scene s;
  s.domain.max = {side, side, side};
  s.domain.cell = 0.01;
  s.time.duration = 1.0;
  s.liquid.push_back({sim::Box{{0, 0, 0}, {side, side / 2, side}}, {}});
  const sim::FluidSolver solver(s);
  const auto path = folder.path() / "frame.vdb";
  writeFrameVdb(path, solver.grid(), solver.particles(), solver.velocity(),
                {solver.particleRadius()});
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::filesystem::path writeBytes(const test::TempFolder& folder, const std::string& bytes) {
  const auto path = folder.path() / "0000.vdb";
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

template <typename T>
void put(std::string& bytes, std::size_t offset, T value) {
  std::memcpy(bytes.data() + offset, &value, sizeof value);
}

template <typename T>
T get(const std::string& bytes, std::size_t offset) {
  T value{};
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  return value;
}

/// Where the value of the frame's delayed-load table (metadata entry `file_delayed_load`, type
/// `__delayedload`) starts: after the type name and the uint32 value size.
std::size_t delayedLoadValue(const std::string& bytes) {
  const std::string type = "__delayedload";
  const std::size_t at = bytes.find(type);
  EXPECT_NE(at, std::string::npos);
  return at + type.size() + 4;
}

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

/// The InputError FrameLevelSet throws for `bytes`, or a failure if it throws none.
InputError frameError(const test::TempFolder& folder, const std::string& bytes) {
  const auto path = writeBytes(folder, bytes);
  try {
    const FrameLevelSet surface(path);
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path.string());
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
    return error;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", "", "");
}

// Claim: a frame fluidsound wrote passes the check (it is what the transfer stage reads).
TEST(VdbFileCheck, AcceptsAFrameFluidsoundWrote) {
  test::TempFolder folder;
  EXPECT_NO_THROW(requireIntactVdbFile(writeBytes(folder, frameBytes(folder))));
}

// Claim: a grid descriptor whose end offset is 0 (the fuzzer's first VDB find: OpenVDB then read
// the next descriptor at the file's start and allocated 1.4 GB for a name whose length was the
// magic number) is refused naming the grid's offsets. Reference: the descriptor's layout.
TEST(VdbFileCheck, RefusesGridOffsetsOutOfOrder) {
  test::TempFolder folder;
  std::string bytes = frameBytes(folder);
  const std::size_t offsets =
      firstDescriptor(bytes) + 4 + 7 + 4 + 16 + 4;  // "surface", "Tree_float_5_4_3", ""
  ASSERT_EQ(bytes.substr(firstDescriptor(bytes) + 4, 7), "surface");
  put<std::int64_t>(bytes, offsets + 16, 0);  // end offset
  const InputError error = frameError(folder, bytes);
  EXPECT_EQ(error.field(), "grid 0 offsets");
}

// Claim: a block offset past the end of the grid's topology is refused naming it. OpenVDB reads
// the leaves' values right after the topology whatever the offset says; a fuzzed file
// (tests/fuzz/corpus/frame_vdb/block_offset_past_topology.vdb) had the check validate the bytes at
// the offset while OpenVDB allocated a 0x7f…-byte blosc buffer from the bytes before it. Here the
// offset moved one byte on, within the file and still before the end offset.
TEST(VdbFileCheck, RefusesABlockOffsetPastTheTopology) {
  test::TempFolder folder;
  std::string bytes = frameBytes(folder);
  const std::size_t offsets = firstDescriptor(bytes) + 4 + 7 + 4 + 16 + 4;
  ASSERT_EQ(bytes.substr(firstDescriptor(bytes) + 4, 7), "surface");
  put<std::int64_t>(bytes, offsets + 8, get<std::int64_t>(bytes, offsets + 8) + 1);  // block offset
  const InputError error = frameError(folder, bytes);
  EXPECT_EQ(error.field(), "grid 0 block offset");
}

// Claim: a string length beyond the file is refused naming the string, not allocated.
TEST(VdbFileCheck, RefusesAStringLongerThanTheFile) {
  test::TempFolder folder;
  std::string bytes = frameBytes(folder);
  put<std::uint32_t>(bytes, firstDescriptor(bytes), 0xfffffff0u);  // the first grid's name length
  const InputError error = frameError(folder, bytes);
  EXPECT_EQ(error.field(), "grid 0 name");
  EXPECT_EQ(error.found(), "4294967280");
}

// Claim: a count beyond what the file could hold is refused naming it, and so is more than 1024
// grids where the file could hold their descriptors (36 bytes each at least).
TEST(VdbFileCheck, RefusesAGridCountBeyondTheFile) {
  test::TempFolder folder;
  std::string bytes = frameBytes(folder);
  put<std::int32_t>(bytes, firstDescriptor(bytes) - 4, 1 << 30);
  EXPECT_EQ(frameError(folder, bytes).field(), "grid count");
  ASSERT_GT(bytes.size(), 1025u * 36);
  put<std::int32_t>(bytes, firstDescriptor(bytes) - 4, 1025);
  const InputError error = frameError(folder, bytes);
  EXPECT_EQ(error.field(), "grid count");
  EXPECT_EQ(error.expected(), "a grid count from 0 to 1024");
}

// Claim: a file cut inside its header, or one of another kind, is refused naming the part.
TEST(VdbFileCheck, RefusesATruncatedHeaderAndAnotherKindOfFile) {
  test::TempFolder folder;
  const std::string bytes = frameBytes(folder);
  EXPECT_EQ(frameError(folder, bytes.substr(0, 40)).field(), "UUID");
  EXPECT_EQ(frameError(folder, "not a VDB file at all").field(), "magic number");
  EXPECT_EQ(frameError(folder, "").field(), "magic number");
}

// Claim: a node whose raw (uncompressed) block is not the node's size is refused naming it:
// OpenVDB 10 read such a block into the node's buffer before comparing the sizes, writing past it
// (AddressSanitizer: heap-buffer-overflow in io::bloscFromStream; the fuzzer's input, committed).
TEST(VdbFileCheck, RefusesARawBlockLargerThanItsNode) {
  const std::filesystem::path frame = std::filesystem::path(FLUIDSOUND_SOURCE_DIR) /
                                      "tests/fuzz/corpus/frame_vdb/raw_chunk_larger_than_node.vdb";
  try {
    requireIntactVdbFile(frame);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "grid 0 root child 0 values size");
    EXPECT_EQ(error.found(), "-5208204135685572680");
  }
}

// Claim: a compressed block larger than what is left of the file is refused before OpenVDB
// allocates it (the fuzzer's 86 GB block). Reference: the file's size.
TEST(VdbFileCheck, RefusesACompressedBlockBeyondTheFile) {
  const std::filesystem::path frame = std::filesystem::path(FLUIDSOUND_SOURCE_DIR) /
                                      "tests/fuzz/corpus/frame_vdb/blosc_block_size_86gb.vdb";
  EXPECT_THROW(requireIntactVdbFile(frame), InputError);
}

/// The corpus input `name` (tests/fuzz/corpus/frame_vdb/).
std::filesystem::path corpusFrame(const std::string& name) {
  return std::filesystem::path(FLUIDSOUND_SOURCE_DIR) / "tests/fuzz/corpus/frame_vdb" / name;
}

/// The InputError requireIntactVdbFile throws for `path`, or a failure if it throws none.
InputError checkError(const std::filesystem::path& path) {
  try {
    requireIntactVdbFile(path);
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path.string());
    return error;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", "", "");
}

// Claim: the open finding of frame_vdb_fuzz (OpenVDB 10's io::DelayedLoadMetadata::readValue
// allocated 1 775 002 321 bytes, the mask array's size, which it never compares with the value's
// size) is refused naming that size, and so are the compressed sizes' size and a node count
// beyond the file. Reference: the layout of io/DelayedLoadMetadata.cc (node count, then per array
// a size and its bytes); the 4-cell frame's table is raw (both sizes 0).
TEST(VdbFileCheck, RefusesADelayedLoadSizeBeyondItsValue) {
  test::TempFolder folder;
  const std::string good = frameBytes(folder);
  const std::size_t value = delayedLoadValue(good);
  const auto nodes = get<std::uint32_t>(good, value);
  ASSERT_EQ(nodes, 8u);                                        // the frame's 8 leaves
  ASSERT_EQ(get<std::uint32_t>(good, value + 4), 0u);          // masks: raw
  ASSERT_EQ(get<std::uint32_t>(good, value + 8 + nodes), 0u);  // compressed sizes: raw

  std::string bytes = good;
  put<std::uint32_t>(bytes, value + 4, 1775002321u);
  InputError error = frameError(folder, bytes);
  EXPECT_TRUE(endsWith(error.field(), " value masks size")) << error.what();
  EXPECT_EQ(error.found(), "1775002321");

  bytes = good;
  put<std::uint32_t>(bytes, value + 8 + nodes, 1775002321u);
  error = frameError(folder, bytes);
  EXPECT_TRUE(endsWith(error.field(), " value compressed sizes size")) << error.what();

  bytes = good;
  put<std::uint32_t>(bytes, value, 0xfffffff0u);
  error = frameError(folder, bytes);
  EXPECT_TRUE(endsWith(error.field(), " value node count")) << error.what();
  EXPECT_EQ(error.found(), "4294967280");

  EXPECT_TRUE(endsWith(checkError(corpusFrame("delayed_load_mask_size_1775002321.vdb")).field(),
                       " value masks size"));
}

// Claim: a blosc block in the delayed-load table whose header says more than the table holds is
// refused naming the header's field: OpenVDB reserves the header's uncompressed size, blosc
// trusts its block and compressed sizes. Reference: blosc's 16-byte header (version, version of
// the codec, flags, type size, then uint32 uncompressed, block and compressed sizes).
TEST(VdbFileCheck, RefusesADelayedLoadBloscHeaderThatLies) {
  test::TempFolder folder;
  std::string good = frameBytes(folder);
  const std::size_t value = delayedLoadValue(good);
  const auto nodes = get<std::uint32_t>(good, value);
  const std::size_t sizes = value + 8 + nodes;  // the compressed sizes' size, then 8 per node
  // The raw array's 64 bytes declared a blosc block of 64 bytes, with a header that holds.
  put<std::uint32_t>(good, sizes, 64);
  put<std::uint32_t>(good, sizes + 4, 0x04010102u);  // version 2, codec 1, flags 1, type size 4
  const auto withHeader = [&](std::uint32_t uncompressed, std::uint32_t block,
                              std::uint32_t compressed) {
    std::string bytes = good;
    put(bytes, sizes + 8, uncompressed);
    put(bytes, sizes + 12, block);
    put(bytes, sizes + 16, compressed);
    return checkError(writeBytes(folder, bytes));
  };
  InputError error = withHeader(0x7fffffffu, 64, 64);
  EXPECT_TRUE(endsWith(error.field(), " value compressed sizes uncompressed size")) << error.what();
  EXPECT_EQ(error.found(), "2147483647");
  error = withHeader(64, 1u << 30, 64);
  EXPECT_TRUE(endsWith(error.field(), " value compressed sizes block size")) << error.what();
  error = withHeader(64, 64, 1u << 30);
  EXPECT_TRUE(endsWith(error.field(), " value compressed sizes compressed size")) << error.what();
  error = withHeader(64, 64, 8);
  EXPECT_TRUE(endsWith(error.field(), " value compressed sizes compressed size")) << error.what();
  put<std::uint32_t>(good, sizes, 8);  // shorter than a blosc header
  error = withHeader(64, 64, 64);
  EXPECT_TRUE(endsWith(error.field(), " value compressed sizes size")) << error.what();
}

// Claim: a delayed-load table that OpenVDB compressed with blosc passes the check, and the
// frame reads. Reference: a 10-cell frame, whose table OpenVDB writes with a blosc block.
TEST(VdbFileCheck, AcceptsABloscCompressedDelayedLoadTable) {
  test::TempFolder folder;
  const std::string bytes = frameBytes(folder, 10);
  const std::size_t value = delayedLoadValue(bytes);
  const auto nodes = get<std::uint32_t>(bytes, value);
  const auto masks = get<std::uint32_t>(bytes, value + 4);
  const auto sizes = get<std::uint32_t>(bytes, value + 8 + (masks == 0 ? nodes : masks));
  ASSERT_TRUE(masks != 0 || (sizes != 0 && sizes != 0xffffffffu))
      << nodes << " nodes: no blosc block in the table";
  const auto path = writeBytes(folder, bytes);
  EXPECT_NO_THROW(requireIntactVdbFile(path));
  EXPECT_NO_THROW(FrameLevelSet{path});
}

// Claim: a metadata value of a fixed-size type whose size is another is refused: OpenVDB reads
// the type's size whatever the file says, then reads the next entry from the wrong place (the
// fuzzer's input, committed: an int32 of 12 bytes, then a name length of 4 GiB allocated).
TEST(VdbFileCheck, RefusesAFixedSizeMetadataValueOfAnotherSize) {
  test::TempFolder folder;
  std::string bytes = frameBytes(folder);
  const std::size_t type = bytes.find("vec3i");  // file_bbox_max
  ASSERT_NE(type, std::string::npos);
  ASSERT_EQ(get<std::uint32_t>(bytes, type + 5), 12u);
  put<std::uint32_t>(bytes, type + 5, 13);
  const InputError error = frameError(folder, bytes);
  EXPECT_TRUE(endsWith(error.field(), " value size")) << error.what();
  EXPECT_EQ(error.expected(), "12 bytes (the size of type vec3i)");
  EXPECT_EQ(error.found(), "13");

  const InputError fuzzed = checkError(corpusFrame("int32_metadata_size_12.vdb"));
  EXPECT_EQ(fuzzed.expected(), "4 bytes (the size of type int32)");
  EXPECT_EQ(fuzzed.found(), "12");
}

// Claim: every grid's transform type is checked, not only the surface's: OpenVDB reads it for
// any grid it reads. Reference: the grid renamed `surfacf`, its transform type's length 2 GiB.
TEST(VdbFileCheck, RefusesATransformTypeBeyondAnyGrid) {
  test::TempFolder folder;
  std::string bytes = frameBytes(folder);
  ASSERT_EQ(bytes.substr(firstDescriptor(bytes) + 4, 7), "surface");
  bytes[firstDescriptor(bytes) + 10] = 'f';
  const std::size_t map = bytes.find("UniformScaleTranslateMap");
  ASSERT_NE(map, std::string::npos);
  put<std::uint32_t>(bytes, map - 4, 0x7ffffff0u);
  const InputError error = checkError(writeBytes(folder, bytes));
  EXPECT_EQ(error.field(), "grid 0 transform");
  EXPECT_EQ(error.found(), "2147483632");
}

// Claim: a truncated or damaged frame is one InputError naming the file, never std::bad_alloc, a
// crash or another exception: the frame cut at 40 lengths from 0 bytes to all but one, and with
// each of its first 340 bytes (the header: magic, version, UUID, file metadata, the first grid's
// descriptor and metadata, up to its delayed-load table) set to 0xff, one at a time. Byte 68 (the
// high byte of the grid name's length) made OpenVDB zero 4 GiB before the check.
TEST(VdbFileCheck, TruncatedOrDamagedFrameIsAnInputError) {
  test::TempFolder folder;
  const std::string bytes = frameBytes(folder, 10);
  ASSERT_GT(bytes.size(), 340u);
  const std::filesystem::path bad = folder.path() / "bad.vdb";
  const auto expectInputErrorOrSurface = [&](const std::string& content, const std::string& what) {
    std::ofstream(bad, std::ios::binary | std::ios::trunc) << content;
    try {
      const FrameLevelSet surface(bad);  // a damaged value inside the tree may still read
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), bad.string()) << what;
      EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos)
          << what << ": " << error.what();
    } catch (const std::exception& error) {
      ADD_FAILURE() << what << ": not an InputError: " << error.what();
    }
  };
  for (std::size_t k = 0; k < 40; ++k) {
    const std::size_t length = k * (bytes.size() - 1) / 39;
    expectInputErrorOrSurface(bytes.substr(0, length), "cut at " + std::to_string(length));
  }
  for (std::size_t at = 0; at < 340; ++at) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(0xff);
    expectInputErrorOrSurface(damaged, "byte " + std::to_string(at) + " set to 0xff");
  }
}

}  // namespace
}  // namespace fluidsound::io

#include <openvdb/openvdb.h>

namespace fluidsound::io {
namespace {

/// A file holding one Vec3 grid `velocity` (a 16³ block of active voxels, OpenVDB's default
/// compression), its values saved as half floats when `half`.
std::string velocityFileBytes(const test::TempFolder& folder, bool half) {
  openvdb::initialize();
  auto grid = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
  grid->setName("velocity");
  grid->setSaveFloatAsHalf(half);
  auto accessor = grid->getAccessor();
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j)
      for (int k = 0; k < 16; ++k) accessor.setValue({i, j, k}, openvdb::Vec3s(0.1f * i, -0.2f * j, 0.3f * k));
  const auto path = folder.path() / (half ? "half.vdb" : "full.vdb");
  openvdb::io::File(path.string()).write({grid});
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Claim: the trees of Vec3 grids (a cache's velocity) are checked as the level set's are — the
// values 12 bytes each, 6 when saved as half floats (Houdini's default; OpenVDB's
// is_saved_as_half_float) — so a file OpenVDB wrote passes either way, and a leaf whose
// compressed size says more than its grid holds is refused naming the leaf before OpenVDB
// allocates it (the gap from-cache had: a crafted velocity grid ended as std::bad_alloc, exit 5).
// Reference: the layout of the leaves' values after the topology (io/Compression.h): the value
// mask (64 bytes), the kind byte, then the int64 compressed size.
TEST(VdbFileCheck, ChecksVec3TreesFullAndHalf) {
  test::TempFolder folder;
  for (const bool half : {false, true}) {
    std::string bytes = velocityFileBytes(folder, half);
    EXPECT_NO_THROW(requireIntactVdbFile(writeBytes(folder, bytes))) << "half " << half;
    const std::size_t name = bytes.find(std::string("\x08\0\0\0velocity", 12));
    ASSERT_NE(name, std::string::npos);
    // The type as written: "_HalfFloat" after it for a grid saved as half floats.
    const std::string type = half ? "Tree_vec3s_5_4_3_HalfFloat" : "Tree_vec3s_5_4_3";
    ASSERT_EQ(get<std::uint32_t>(bytes, name + 12), type.size());
    ASSERT_EQ(bytes.substr(name + 16, type.size()), type);
    const std::size_t offsets = name + 4 + 8 + 4 + type.size() + 4;
    const auto block = static_cast<std::size_t>(get<std::int64_t>(bytes, offsets + 8));
    put<std::int64_t>(bytes, block + 64 + 1, std::int64_t{1} << 40);  // the first leaf's compressed size
    const InputError error = checkError(writeBytes(folder, bytes));
    EXPECT_EQ(error.field(), "grid 0 leaf 0 values data") << error.what();
  }
}

}  // namespace
}  // namespace fluidsound::io
