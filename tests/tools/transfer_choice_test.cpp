// Tests of the transfer model's choice (tools/transfer_choice.h): `--transfer image|geometric` on
// `transfer` and `run` over the scene's transfer.model, through the real executable. The image
// model gives the bytes the stage's library function gives (as before the geometric model came).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "acoustics/transfer/level_set_surface.h"
#include "acoustics/transfer/transfer_stage.h"
#include "io/bubble_track_file.h"
#include "io/frame_surface.h"
#include "io/scene_file.h"
#include "support/command_runner.h"
#include "support/falling_column_scene.h"
#include "support/file_bytes.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

// Claim: an unknown model name is a usage error (exit 2) naming --transfer, before any work, on
// both commands that take it.
TEST(TransferChoice, UnknownModelNameIsAUsageErrorNamingTheOption) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", out = folder.path() / "out";
  writeFile(scene, kFallingColumnScene);
  for (const char* command : {"transfer", "run"}) {
    const CommandOutcome outcome =
        runFluidsound({command, scene.string(), "-o", out.string(), "--transfer", "nonsense"});
    EXPECT_EQ(outcome.exitCode, 2) << command << ": " << outcome.err;
    EXPECT_NE(outcome.err.find("--transfer"), std::string::npos) << command << ": " << outcome.err;
    EXPECT_FALSE(fs::exists(out)) << command << " wrote before refusing the option";
  }
}

/// The image-source stage as `transfer` ran it before the geometric model: computeTransfer over
/// the frames' level sets, with the scene's listeners, up, frame rate and the default model.
std::string imageTransferBytes(const fs::path& scenePath, const fs::path& out) {
  const sim::Scene scene = io::readScene(scenePath);
  acoustics::TransferSetup setup;
  for (const sim::Listener& l : scene.listeners) setup.listeners.push_back({l.name, l.position});
  const double g =
      std::sqrt(scene.gravity[0] * scene.gravity[0] + scene.gravity[1] * scene.gravity[1] +
                scene.gravity[2] * scene.gravity[2]);
  setup.up = {-scene.gravity[0] / g, -scene.gravity[1] / g, -scene.gravity[2] / g};
  setup.fps = scene.time.fps;
  setup.lastFrame = static_cast<int>(std::lround(scene.time.duration * scene.time.fps));
  const io::FrameFolderLevelSets levelSets(out);
  const acoustics::LevelSetFrameSurfaces frames(levelSets);
  StageObserver quiet;
  acoustics::TransferResult result = acoustics::computeTransfer(
      io::readBubbleTracks(out / "bubbles.json", io::TransferValues::Optional), frames, setup,
      quiet);
  const fs::path file = out / "reference.bubbles.json";
  io::writeBubbleTracks(file, result.tracks);
  return fileBytes(file);
}

// Claim: `run --transfer image` and `transfer --transfer image` write the bubbles.json bytes of
// the image-source stage function itself (the model's results unchanged by the choice), and a
// scene whose transfer.model is "image" gives the same without the option; the reports name the
// model. Reference: acoustics::computeTransfer on the same simulated folder.
TEST(TransferChoice, ImageModelGivesTheStageFunctionsBytes) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", run = folder.path() / "run";
  std::string text = kFallingColumnScene;
  text.replace(text.find("0.4,"), 4, "0.25,");  // a few bubbles, over several frames
  writeFile(scene, text);
  const CommandOutcome ran =
      runFluidsound({"run", scene.string(), "-o", run.string(), "--quiet", "--transfer", "image"});
  ASSERT_EQ(ran.exitCode, 0) << ran.err;
  const std::string runBytes = fileBytes(run / "bubbles.json");
  const nlohmann::json tracks = nlohmann::json::parse(runBytes);
  ASSERT_FALSE(tracks["bubbles"].empty()) << "the scene should make bubbles";
  EXPECT_EQ(runBytes, imageTransferBytes(scene, run));
  EXPECT_EQ(nlohmann::json::parse(fileBytes(run / "transfer.report.json"))["settings"]["model"],
            "image");
  EXPECT_EQ(nlohmann::json::parse(fileBytes(run / "report.json"))["run"]["transfer"]["model"],
            "image");

  // The scene's field instead of the option, through `transfer` alone on a copy of the folder.
  const fs::path fieldScene = folder.path() / "field.scene.json", copy = folder.path() / "copy";
  nlohmann::json withField = nlohmann::json::parse(text);
  withField["transfer"] = {{"model", "image"}};
  writeFile(fieldScene, withField.dump());
  fs::copy(run, copy, fs::copy_options::recursive);
  const CommandOutcome transfer =
      runFluidsound({"transfer", fieldScene.string(), "-o", copy.string(), "--quiet"});
  ASSERT_EQ(transfer.exitCode, 0) << transfer.err;
  EXPECT_EQ(fileBytes(copy / "bubbles.json"), runBytes);
  const nlohmann::json report = nlohmann::json::parse(fileBytes(copy / "transfer.report.json"));
  EXPECT_EQ(report["settings"]["model"], "image");
  EXPECT_FALSE(report["results"].contains("geometric")) << "no solver statistics for image";
}

// Claim (issue 19): `run --transfer geometric` fills finite transfers ≥ 0 in every sample, and
// transfer.report.json and report.json's run.transfer name the model, its settings and its
// solver statistics; switching the model on a finished run runs transfer again but reuses the
// simulation.
TEST(TransferChoice, GeometricModelGivesFiniteTransfersAndItsStatistics) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", out = folder.path() / "out";
  std::string text = kFallingColumnScene;
  text.replace(text.find("0.4,"), 4, "0.25,");
  writeFile(scene, text);
  const CommandOutcome image =
      runFluidsound({"run", scene.string(), "-o", out.string(), "--quiet", "--transfer", "image"});
  ASSERT_EQ(image.exitCode, 0) << image.err;
  const CommandOutcome geometric = runFluidsound(
      {"run", scene.string(), "-o", out.string(), "--quiet", "--transfer", "geometric"});
  ASSERT_EQ(geometric.exitCode, 0) << geometric.err;
  const nlohmann::json tracks = nlohmann::json::parse(fileBytes(out / "bubbles.json"));
  std::size_t samples = 0;
  for (const auto& bubble : tracks["bubbles"])
    for (const auto& sample : bubble["track"])
      for (const auto& value : sample["transfer"]) {
        const double t = value.get<double>();
        EXPECT_TRUE(std::isfinite(t) && t >= 0.0) << sample.dump();
        ++samples;
      }
  EXPECT_GT(samples, 0u);
  const nlohmann::json run = nlohmann::json::parse(fileBytes(out / "report.json"))["run"];
  EXPECT_TRUE(run["stages"]["simulate"]["reused"].get<bool>());
  EXPECT_FALSE(run["stages"]["transfer"]["reused"].get<bool>()) << "the model changed";
  const nlohmann::json report = nlohmann::json::parse(fileBytes(out / "transfer.report.json"));
  EXPECT_EQ(report["settings"]["model"], "geometric");
  EXPECT_EQ(report["settings"]["max_bands"], 256);
  ASSERT_TRUE(report["results"].contains("geometric"));
  const nlohmann::json& stats = report["results"]["geometric"];
  for (const char* key :
       {"reciprocal_frames", "adjoint_frames", "widened_frames", "mode_limited_frames", "bands",
        "modes", "factorisations",
        "solves", "max_unknowns", "samples_outside_liquid", "max_frequency_hz", "solve_seconds"})
    EXPECT_TRUE(stats.contains(key)) << key;
  EXPECT_GT(stats["factorisations"].get<double>(), 0.0);
  EXPECT_GT(stats["max_frequency_hz"].get<double>(), 0.0);
  EXPECT_EQ(run["transfer"]["model"], "geometric");
  EXPECT_EQ(run["transfer"]["geometric"], stats);
}

}  // namespace
}  // namespace fluidsound::test
