// Tests of `fluidsound simulate` into a folder that holds another run's frames (issue 16 §5):
// the stale frames go, so the folder never mixes two simulations; nothing that is not ours is
// removed or replaced (links, FIFOs and the files they point to are made in a temporary folder).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/frame_folder.h"
#include "support/file_bytes.h"
#include "support/command_runner.h"
#include "support/falling_column_scene.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

/// OUTDIR as a 60-frame run with --ply left it (dummy contents: only the names matter).
void writeSixtyFrameRun(const fs::path& out) {
  fs::create_directories(out / "frames");
  for (int f = 0; f <= 60; ++f) {
    writeText(out / "frames" / io::frameFileName(f, "vdb"), "frame of another run");
    writeText(out / "frames" / io::frameFileName(f, "ply"), "particles of another run");
  }
  writeText(out / "bubbles.json", "bubbles of another run");
}

// Issue 16 §5: `--frames 3:5` into a 60-frame folder left frames 6–60 and the old PLYs beside
// the new bubbles.json. Now only this run's frames 3–5 remain; a file that is not a frame stays
// (with a warning naming it), and a link named like a frame is removed, never its target.
TEST(SimulateStaleFrames, AnotherRunsFramesAreRemoved) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", out = folder.path() / "out";
  writeText(scene, kFallingColumnScene);
  writeSixtyFrameRun(out);
  writeText(out / "frames" / "notes.txt", "my notes");
  writeText(folder.path() / "precious.ply", "not the simulation's");
  fs::remove(out / "frames" / "0042.ply");
  fs::create_symlink(folder.path() / "precious.ply", out / "frames" / "0042.ply");

  const CommandOutcome r =
      runFluidsound({"simulate", scene.string(), "-o", out.string(), "--frames", "3:5"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(out / "frames"))
    left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"0003.vdb", "0004.vdb", "0005.vdb", "notes.txt"}));
  EXPECT_NE(fileBytes(out / "frames" / "0004.vdb"), "frame of another run");
  EXPECT_NE(fileBytes(out / "bubbles.json"), "bubbles of another run");
  EXPECT_EQ(fileBytes(folder.path() / "precious.ply"), "not the simulation's")
      << "a link's target is not ours";
  EXPECT_EQ(fileBytes(out / "frames" / "notes.txt"), "my notes");
  EXPECT_NE(r.err.find("removed 119 stale frame file(s) of another run"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("warning: " + (out / "frames").string() +
                       ": left 1 entry that is not frames of this run: notes.txt"),
            std::string::npos)
      << r.err;
}

// A FIFO where a frame is to be written is not replaced: one line naming it, exit 4, before the
// simulation and before anything is removed (the stale frames and bubbles.json stay as they were).
TEST(SimulateStaleFrames, AFifoWhereAFrameGoesIsRefused) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", out = folder.path() / "out";
  writeText(scene, kFallingColumnScene);
  writeSixtyFrameRun(out);
  fs::remove(out / "frames" / "0004.vdb");
  ASSERT_EQ(::mkfifo((out / "frames" / "0004.vdb").c_str(), 0600), 0);

  const CommandOutcome r =
      runFluidsound({"simulate", scene.string(), "-o", out.string(), "--frames", "3:5", "-q"});
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_EQ(r.err, "fluidsound: error: " + (out / "frames" / "0004.vdb").string() +
                       ": cannot write the frame: it is a FIFO, not a file a simulation wrote; "
                       "remove it or choose "
                       "another output folder\n");
  EXPECT_TRUE(fs::is_fifo(out / "frames" / "0004.vdb"));
  EXPECT_EQ(fileBytes(out / "frames" / "0060.ply"), "particles of another run");
  EXPECT_EQ(fileBytes(out / "bubbles.json"), "bubbles of another run");
  EXPECT_FALSE(fs::exists(out / "report.json"));
}

}  // namespace
}  // namespace fluidsound::test
