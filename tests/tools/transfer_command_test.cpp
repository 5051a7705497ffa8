// Tests of `fluidsound transfer` (tools/transfer_command.h) through the real executable: frames
// are evaluated in parallel, and the file it writes does not depend on the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/file_bytes.h"
#include "support/command_runner.h"
#include "support/falling_column_scene.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = kFallingColumnScene;

// Claim: the transfer stage writes the same bubbles.json, byte for byte, with 1, 2 or 3 threads
// (each track sample belongs to one frame and is written by that frame's task alone), and it
// fills a transfer value per listener in every sample. Reference: the one-thread file.
TEST(TransferCommand, OutputDoesNotDependOnTheThreadCount) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", simulated = folder.path() / "simulated";
  { std::ofstream(scene) << kScene; }
  const CommandOutcome simulate = runFluidsound({"simulate", scene.string(), "-o", simulated.string(), "--quiet"});
  ASSERT_EQ(simulate.exitCode, 0) << simulate.err;
  std::string reference;
  for (const char* threads : {"1", "2", "3"}) {
    const fs::path out = folder.path() / (std::string("threads") + threads);
    fs::copy(simulated, out, fs::copy_options::recursive);
    const CommandOutcome transfer =
        runFluidsound({"transfer", scene.string(), "-o", out.string(), "--quiet", "--threads", threads});
    ASSERT_EQ(transfer.exitCode, 0) << transfer.err;
    const std::string text = fileBytes(out / "bubbles.json");
    if (reference.empty()) {
      reference = text;
      const nlohmann::json tracks = nlohmann::json::parse(text);
      ASSERT_FALSE(tracks["bubbles"].empty()) << "the scene should make bubbles";
      std::size_t samples = 0;
      for (const auto& bubble : tracks["bubbles"])
        for (const auto& sample : bubble["track"]) {
          ASSERT_EQ(sample["transfer"].size(), 2u) << sample.dump();
          ++samples;
        }
      EXPECT_GT(samples, tracks["bubbles"].size()) << "tracks should span several frames";
    } else {
      EXPECT_TRUE(text == reference) << threads << " threads wrote another bubbles.json";
    }
  }
}

// Bad input: frames whose surface grid has a raw block longer than its node (found by
// tests/fuzz/frame_vdb_fuzz; OpenVDB wrote past the node's buffer: a segmentation fault, exit 139)
// end the transfer with exit 3 and one line naming the frame and the node, and leave the folder as
// it was (bubbles.json unchanged, no report).
TEST(TransferCommand, CorruptFrameIsAOneLineInputError) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", out = folder.path() / "out";
  { std::ofstream(scene) << kScene; }
  const CommandOutcome simulate =
      runFluidsound({"simulate", scene.string(), "-o", out.string(), "--quiet"});
  ASSERT_EQ(simulate.exitCode, 0) << simulate.err;
  const fs::path corrupt = fs::path(FLUIDSOUND_SOURCE_DIR) /
                           "tests/fuzz/corpus/frame_vdb/raw_chunk_larger_than_node.vdb";
  for (const auto& frame : fs::directory_iterator(out / "frames"))
    if (frame.path().extension() == ".vdb")
      fs::copy_file(corrupt, frame.path(), fs::copy_options::overwrite_existing);
  const std::string tracks = fileBytes(out / "bubbles.json");
  std::vector<fs::path> before;
  for (const auto& entry : fs::recursive_directory_iterator(out)) before.push_back(entry.path());

  const CommandOutcome transfer =
      runFluidsound({"transfer", scene.string(), "-o", out.string(), "--quiet"});
  EXPECT_EQ(transfer.exitCode, 3) << transfer.err;
  EXPECT_NE(transfer.err.find("frames/0"), std::string::npos) << transfer.err;
  EXPECT_NE(transfer.err.find("root child 0 values size: expected a compressed size > 0"),
            std::string::npos)
      << transfer.err;
  EXPECT_EQ(transfer.err.find('\n'), transfer.err.size() - 1) << transfer.err;
  EXPECT_EQ(fileBytes(out / "bubbles.json"), tracks);
  std::vector<fs::path> after;
  for (const auto& entry : fs::recursive_directory_iterator(out)) after.push_back(entry.path());
  std::sort(before.begin(), before.end());
  std::sort(after.begin(), after.end());
  EXPECT_EQ(after, before);
}

}  // namespace
}  // namespace fluidsound::test
