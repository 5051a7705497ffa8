// Tests of io/vdb_file_check.h: a corrupt .vdb header is refused with a one-line InputError
// naming the file and the part of the header, before OpenVDB allocates what its lengths say
// (cases found by tests/fuzz/frame_vdb_fuzz; their inputs are in tests/fuzz/corpus/frame_vdb/).
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
#include "sim/fluid_solver.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

// The layout of a frame written by writeFrameVdb (OpenVDB 10, file format 224): the first grid
// descriptor starts after the 57-byte header and the empty file metadata (4) and grid count (4).
constexpr std::size_t kFirstDescriptor = 65;

/// The bytes of frames/0000.vdb of a resting layer in a 4-cell box.
std::string frameBytes(const test::TempFolder& folder) {
  sim::Scene s;
  s.domain.max = {0.04, 0.04, 0.04};
  s.domain.cell = 0.01;
  s.time.duration = 1.0;
  s.liquid.push_back({sim::Box{{0, 0, 0}, {0.04, 0.02, 0.04}}, {}});
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

/// The InputError FrameSurface throws for `bytes`, or a failure if it throws none.
InputError frameError(const test::TempFolder& folder, const std::string& bytes) {
  const auto path = writeBytes(folder, bytes);
  try {
    const FrameSurface surface(path);
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
      kFirstDescriptor + 4 + 7 + 4 + 16 + 4;  // "surface", "Tree_float_5_4_3", ""
  ASSERT_EQ(bytes.substr(kFirstDescriptor + 4, 7), "surface");
  put<std::int64_t>(bytes, offsets + 16, 0);  // end offset
  const InputError error = frameError(folder, bytes);
  EXPECT_EQ(error.field(), "grid 0 offsets");
}

// Claim: a string length beyond the file is refused naming the string, not allocated.
TEST(VdbFileCheck, RefusesAStringLongerThanTheFile) {
  test::TempFolder folder;
  std::string bytes = frameBytes(folder);
  put<std::uint32_t>(bytes, kFirstDescriptor, 0xfffffff0u);  // the first grid's name length
  const InputError error = frameError(folder, bytes);
  EXPECT_EQ(error.field(), "grid 0 name");
  EXPECT_EQ(error.found(), "4294967280");
}

// Claim: a count beyond what the file could hold is refused naming it.
TEST(VdbFileCheck, RefusesAGridCountBeyondTheFile) {
  test::TempFolder folder;
  std::string bytes = frameBytes(folder);
  put<std::int32_t>(bytes, kFirstDescriptor - 4, 1 << 30);
  EXPECT_EQ(frameError(folder, bytes).field(), "grid count");
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

}  // namespace
}  // namespace fluidsound::io
