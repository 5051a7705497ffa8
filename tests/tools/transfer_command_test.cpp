// Tests of `fluidsound transfer` (tools/transfer_command.h) through the real executable: frames
// are evaluated in parallel, and the file it writes does not depend on the thread count.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "support/command_runner.h"
#include "support/falling_column_scene.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = kFallingColumnScene;

std::string fileText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

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
    const std::string text = fileText(out / "bubbles.json");
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

}  // namespace
}  // namespace fluidsound::test
