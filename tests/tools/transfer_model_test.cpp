// Tests of `fluidsound transfer` and `fluidsound run` through the real executable: one oscillator
// model per run (transfer takes synth's model switches, run passes its own to both stages and
// runs them again when it changes), and the one-line errors the stage's library function reports
// with the file the CLI names.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "support/file_bytes.h"
#include "support/command_runner.h"
#include "support/falling_column_scene.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

/// The falling column simulated into `out`, its scene at `scene`.
void simulateInto(const fs::path& scene, const fs::path& out) {
  writeFile(scene, kFallingColumnScene);
  const CommandOutcome simulate = runFluidsound({"simulate", scene.string(), "-o", out.string(), "--quiet"});
  ASSERT_EQ(simulate.exitCode, 0) << simulate.err;
}

// Claim: `transfer --thermal` computes ω with the thermal polytropic index: some transfer values
// change (listeners outside a bubble's critical cone depend on ω), and the report names the model.
// Reference: the default model's file from the same simulation.
TEST(TransferModel, ThermalSwitchChangesTheValues) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", base = folder.path() / "base";
  simulateInto(scene, base);
  const fs::path thermal = folder.path() / "thermal";
  fs::copy(base, thermal, fs::copy_options::recursive);
  const CommandOutcome a = runFluidsound({"transfer", scene.string(), "-o", base.string(), "--quiet"});
  ASSERT_EQ(a.exitCode, 0) << a.err;
  const CommandOutcome b =
      runFluidsound({"transfer", scene.string(), "-o", thermal.string(), "--quiet", "--thermal"});
  ASSERT_EQ(b.exitCode, 0) << b.err;
  EXPECT_NE(fileBytes(base / "bubbles.json"), fileBytes(thermal / "bubbles.json"));
  const nlohmann::json report = nlohmann::json::parse(fileBytes(thermal / "transfer.report.json"));
  EXPECT_EQ(report["settings"]["oscillator_model"]["polytropic"], "thermal");
}

// Claim: `run --thermal` after a default run reuses the simulation and runs transfer and synth
// again (the model is part of both stages' fingerprints), and both reports name the model.
TEST(TransferModel, RunPassesItsModelToTransferAndSynth) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", out = folder.path() / "out";
  writeFile(scene, kFallingColumnScene);
  const CommandOutcome first = runFluidsound({"run", scene.string(), "-o", out.string(), "--quiet"});
  ASSERT_EQ(first.exitCode, 0) << first.err;
  const CommandOutcome second =
      runFluidsound({"run", scene.string(), "-o", out.string(), "--quiet", "--thermal"});
  ASSERT_EQ(second.exitCode, 0) << second.err;
  const nlohmann::json stages = nlohmann::json::parse(fileBytes(out / "report.json"))["run"]["stages"];
  EXPECT_TRUE(stages["simulate"]["reused"].get<bool>());
  EXPECT_FALSE(stages["transfer"]["reused"].get<bool>());
  EXPECT_FALSE(stages["synth"]["reused"].get<bool>());
  for (const char* report : {"transfer.report.json", "synth.report.json"})
    EXPECT_EQ(nlohmann::json::parse(fileBytes(out / report))["settings"]["oscillator_model"]["polytropic"],
              "thermal")
        << report;
}

/// Runs transfer on `out`, expecting exit 3 with `message` as its one line and the folder as it was.
void expectTransferInputError(const fs::path& scene, const fs::path& out, const std::string& message) {
  const std::string tracks = fileBytes(out / "bubbles.json");
  const CommandOutcome transfer = runFluidsound({"transfer", scene.string(), "-o", out.string(), "--quiet"});
  EXPECT_EQ(transfer.exitCode, 3) << transfer.err;
  EXPECT_NE(transfer.err.find(message), std::string::npos) << transfer.err;
  EXPECT_EQ(transfer.err.find('\n'), transfer.err.size() - 1) << transfer.err;
  EXPECT_EQ(fileBytes(out / "bubbles.json"), tracks);
  EXPECT_FALSE(fs::exists(out / "transfer.report.json"));
}

// Bad input: a track sample without a position is named in bubbles.json (exit 3, nothing written).
TEST(TransferModel, SampleWithoutPositionNamesTheTracksFile) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", out = folder.path() / "out";
  simulateInto(scene, out);
  nlohmann::json tracks = nlohmann::json::parse(fileBytes(out / "bubbles.json"));
  ASSERT_FALSE(tracks["bubbles"].empty());
  tracks["bubbles"][0]["track"][0].erase("position");
  writeFile(out / "bubbles.json", tracks.dump());
  expectTransferInputError(scene, out,
                           (out / "bubbles.json").string() +
                               ": bubbles[0].track[0]: expected a position (written by fluidsound "
                               "simulate), found none");
}

// Bad input: a listener moved onto a bubble's centre is named in the scene file (exit 3). A rule
// of the image-source model (its distance to the listener and the surface point), so the scene
// asks for that model.
TEST(TransferModel, ListenerOnABubbleNamesTheSceneFile) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", out = folder.path() / "out";
  simulateInto(scene, out);
  const nlohmann::json tracks = nlohmann::json::parse(fileBytes(out / "bubbles.json"));
  ASSERT_FALSE(tracks["bubbles"].empty());
  nlohmann::json sceneJson = nlohmann::json::parse(kFallingColumnScene);
  sceneJson["listeners"][1]["position"] = tracks["bubbles"][0]["track"][0]["position"];
  sceneJson["transfer"] = {{"model", "image"}};
  writeFile(scene, sceneJson.dump());
  expectTransferInputError(scene, out,
                           scene.string() +
                               ": listeners[1].position: expected a listener away from every "
                               "bubble and its surface point, found ");
}

}  // namespace
}  // namespace fluidsound::test
