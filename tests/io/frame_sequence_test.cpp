// tests/io/frame_sequence_test.cpp — a cache's frame sequence (io/frame_sequence.h; issue 21):
// each pattern style finds its files in frame order, and each problem is one error naming the
// cache file, the field and what was expected.
#include "io/frame_sequence.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& path) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << "x";
}

std::vector<int> framesOf(const std::vector<SequenceFrame>& sequence) {
  std::vector<int> frames;
  for (const SequenceFrame& f : sequence) frames.push_back(f.frame);
  return frames;
}

/// The error frameSequence throws for `pattern` in `folder`, as one line.
std::string errorOf(const std::string& pattern, const fs::path& folder) {
  try {
    frameSequence(pattern, folder, "cache.json", "frames");
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "frames");
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    return e.what();
  }
  ADD_FAILURE() << "no error for " << pattern;
  return {};
}

TEST(FrameSequence, EachPatternStyleFindsItsFramesInOrder) {
  test::TempFolder folder;
  for (int f : {2, 0, 1}) touch(folder.path() / "frames" / (std::string("000") + std::to_string(f) + ".vdb"));
  touch(folder.path() / "frames" / "0001.ply");  // another kind of file beside them
  EXPECT_EQ(framesOf(frameSequence("frames", folder.path(), "cache.json", "frames")), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(framesOf(frameSequence("frames/%04d.vdb", folder.path(), "cache.json", "frames")), (std::vector<int>{0, 1, 2}));
  const auto sequence = frameSequence("frames/%04d.vdb", folder.path(), "cache.json", "frames");
  EXPECT_EQ(sequence[1].path, folder.path() / "frames" / "0001.vdb");

  for (int f = 1; f <= 3; ++f) touch(folder.path() / "geo" / ("surface.000" + std::to_string(f) + ".vdb"));
  touch(folder.path() / "geo" / "surface.01.vdb");  // not $F4's name for frame 1
  EXPECT_EQ(framesOf(frameSequence("geo/surface.$F4.vdb", folder.path(), "cache.json", "frames")), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(framesOf(frameSequence("geo/surface.####.vdb", folder.path(), "cache.json", "frames")), (std::vector<int>{1, 2, 3}));

  for (int f = 9; f <= 11; ++f) touch(folder.path() / "flip" / ("flip." + std::to_string(f) + ".vdb"));
  EXPECT_EQ(framesOf(frameSequence("flip/flip.%d.vdb", folder.path(), "cache.json", "frames")), (std::vector<int>{9, 10, 11}));
  EXPECT_EQ(framesOf(frameSequence("flip/flip.$F.vdb", folder.path(), "cache.json", "frames")), (std::vector<int>{9, 10, 11}));
  // An absolute pattern ignores the folder.
  EXPECT_EQ(frameSequence((folder.path() / "flip/flip.%d.vdb").string(), "/nonexistent", "cache.json", "frames").size(), 3u);
}

TEST(FrameSequence, EachProblemIsOneErrorNamingTheField) {
  test::TempFolder folder;
  for (int f : {0, 1, 3}) touch(folder.path() / "frames" / (std::string("000") + std::to_string(f) + ".vdb"));
  const std::string gap = errorOf("frames/%04d.vdb", folder.path());
  EXPECT_NE(gap.find("cache.json: frames: expected every frame from 0 to 3, found no "), std::string::npos) << gap;
  EXPECT_NE(gap.find("0002.vdb"), std::string::npos) << gap;
  const std::string none = errorOf("frames/flip.%04d.vdb", folder.path());
  EXPECT_NE(none.find("expected at least one frame file, found none matching"), std::string::npos) << none;
  EXPECT_NE(errorOf("frames/surface.vdb", folder.path()).find("(0 frame tokens)"), std::string::npos);
  EXPECT_NE(errorOf("frames/%04d.$F4.vdb", folder.path()).find("(2 frame tokens)"), std::string::npos);
  EXPECT_NE(errorOf("$F4/surface.vdb", folder.path()).find("frame tokens"), std::string::npos);
  EXPECT_NE(errorOf("missing/%04d.vdb", folder.path()).find("no such folder"), std::string::npos);
}

}  // namespace
}  // namespace fluidsound::io
