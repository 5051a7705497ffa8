// Tests of io/frame_folder.h: the frame names, and clearing the frames of another run from a
// frames folder while never touching what is not ours (tests/support/temp_folder.h; FIFOs and
// links made inside it).
#include "io/frame_folder.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "io/input_error.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

/// A simulation that writes the VDB frames first … last and no PLY.
FrameWritten vdbFrames(int first, int last) {
  return [=](int frame, std::string_view extension) {
    return extension == "vdb" && frame >= first && frame <= last;
  };
}

TEST(FrameFolder, FrameNamesHaveAtLeastFourDigits) {
  EXPECT_EQ(frameFileName(3, "vdb"), "0003.vdb");
  EXPECT_EQ(frameFileName(12345, "ply"), "12345.ply");
}

// `simulate --frames 3:5` into a folder of another run's frames 0 … 7 with PLYs: only 3 … 5 stay
// (to be rewritten), every other frame file goes; files that are not frames stay and are listed.
TEST(FrameFolder, StaleFramesAreRemovedAndOtherFilesLeft) {
  const test::TempFolder folder;
  for (int f = 0; f <= 7; ++f) {
    writeText(folder.path() / frameFileName(f, "vdb"), "old");
    writeText(folder.path() / frameFileName(f, "ply"), "old");
  }
  writeText(folder.path() / "notes.txt", "mine");
  writeText(folder.path() / "003.vdb", "not a frame name");  // 3 digits
  writeText(folder.path() / "0003.vdb.bak", "a backup");
  fs::create_directory(folder.path() / "0009.vdb");  // a folder named like a frame not written
  const FrameFolderCleanup cleanup = clearStaleFrames(folder.path(), vdbFrames(3, 5));
  EXPECT_EQ(cleanup.removed.size(), 13u) << "vdb 0-2, 6, 7 and all 8 ply";
  EXPECT_EQ(cleanup.foreign.size(), 4u);
  EXPECT_EQ(folder.entries(),
            (std::vector<std::string>{"0003.vdb", "0003.vdb.bak", "0004.vdb", "0005.vdb",
                                      "0009.vdb", "003.vdb", "notes.txt"}));
}

// A symbolic link named like a frame is removed as a link — its target, even a file outside the
// folder, is untouched — also when the run will write that frame (it then writes a regular file).
TEST(FrameFolder, LinksAreRemovedNotTheirTargets) {
  const test::TempFolder folder;
  const fs::path frames = folder.path() / "frames", target = folder.path() / "precious.txt";
  fs::create_directory(frames);
  writeText(target, "keep me");
  fs::create_symlink(target, frames / "0001.vdb");                     // will be written
  fs::create_symlink(target, frames / "0042.ply");                     // stale
  fs::create_symlink(folder.path() / "nowhere", frames / "0002.vdb");  // dangling
  const FrameFolderCleanup cleanup = clearStaleFrames(frames, vdbFrames(0, 5));
  EXPECT_EQ(cleanup.removed.size(), 3u);
  EXPECT_TRUE(fs::is_empty(frames));
  std::ifstream in(target);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "keep me");
}

// A FIFO where a frame is to be written is not ours to replace: an output error naming it, and
// nothing removed (the stale frame beside it stays). A FIFO named like a frame not written is left.
TEST(FrameFolder, AFifoInTheWayIsRefusedBeforeAnythingIsRemoved) {
  const test::TempFolder folder;
  ASSERT_EQ(::mkfifo((folder.path() / "0004.vdb").c_str(), 0600), 0);
  writeText(folder.path() / "0099.vdb", "stale");
  try {
    clearStaleFrames(folder.path(), vdbFrames(0, 5));
    ADD_FAILURE() << "no error for a FIFO at 0004.vdb";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("0004.vdb: cannot write the frame: it is a FIFO"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"0004.vdb", "0099.vdb"}));
  const FrameFolderCleanup cleanup = clearStaleFrames(folder.path(), vdbFrames(0, 3));
  EXPECT_EQ(cleanup.foreign.size(), 1u);
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"0004.vdb"}));
}

// The hidden temporary of a frame (io/atomic_file.h: `.NAME.tmp-PID-HEX16`) left by a killed
// process is removed; one of a live process (this test's) is left, as are look-alikes.
TEST(FrameFolder, TemporariesOfEndedProcessesAreRemoved) {
  const test::TempFolder folder;
  const std::string hex = "0123456789abcdef";
  // PID 2^22 + 1 is above Linux's pid_max limit (4194304), so no process can hold it.
  const std::string dead = ".0003.vdb.tmp-4194305-" + hex;
  const std::string live = ".0004.vdb.tmp-" + std::to_string(::getpid()) + "-" + hex;
  writeText(folder.path() / dead, "half");
  writeText(folder.path() / live, "half");
  writeText(folder.path() / (".notes.tmp-4194305-" + hex), "not a frame's");
  clearStaleFrames(folder.path(), vdbFrames(0, 5));
  EXPECT_EQ(folder.entries(),
            (std::vector<std::string>{".0004.vdb.tmp-" + std::to_string(::getpid()) + "-" + hex,
                                      ".notes.tmp-4194305-" + hex}));
}

TEST(FrameFolder, AMissingFolderIsEmpty) {
  const test::TempFolder folder;
  const FrameFolderCleanup cleanup = clearStaleFrames(folder.path() / "frames", vdbFrames(0, 1));
  EXPECT_TRUE(cleanup.removed.empty());
  EXPECT_TRUE(cleanup.foreign.empty());
}

}  // namespace
}  // namespace fluidsound::io
