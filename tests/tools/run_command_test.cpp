// Tests of `fluidsound run` (tools/run_command.h) through the real executable: the whole pipeline
// from a scene to a WAV, a spectrogram and report.json, reusing up-to-date stages.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "io/audio_file.h"
#include "support/command_runner.h"
#include "support/falling_column_scene.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = kFallingColumnScene;

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(std::string(std::istreambuf_iterator<char>(in), {}));
}

// Claim (issue 6): `run` renders a scene to NAME.wav, spectrogram.png and report.json (stage
// records, bubble count, size histogram, peak level); a second run with unchanged inputs reuses
// every stage; a changed scene runs them all again. Reference: the files and the report's flags.
TEST(RunCommand, RendersTheSceneAndReusesFreshStages) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", out = folder.path() / "out";
  { std::ofstream(scene) << kScene; }
  CommandOutcome first = runFluidsound({"run", scene.string(), "-o", out.string(), "--quiet"});
  ASSERT_EQ(first.exitCode, 0) << first.err;
  for (const char* name : {"fall.wav", "spectrogram.png", "report.json", "bubbles.json", "frames/0012.vdb"})
    EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
  nlohmann::json report = readJson(out / "report.json");
  ASSERT_TRUE(report.contains("run"));
  EXPECT_FALSE(report["run"]["stages"]["simulate"]["reused"].get<bool>());
  EXPECT_EQ(report["run"]["radius_histogram"].size(), 10u);
  EXPECT_TRUE(report["results"].contains("frames")) << "the simulation's per-frame records stay";
  // The spectrum summary (docs/synthesis.md, "What the spectrum shows"): one entry per listener
  // with the measured and predicted centroid; their agreement is tested on a pour in
  // pour_spectrum_test.cpp, here only that the report carries them.
  ASSERT_TRUE(report["run"].contains("spectrum"));
  ASSERT_EQ(report["run"]["spectrum"]["channels"].size(), 2u);
  EXPECT_EQ(report["run"]["spectrum"]["channels"][1]["listener"], "right");
  for (const auto& channel : report["run"]["spectrum"]["channels"]) {
    EXPECT_TRUE(channel.contains("centroid_measured_hz")) << channel.dump();
    EXPECT_TRUE(channel.contains("centroid_predicted_hz")) << channel.dump();
  }

  CommandOutcome second = runFluidsound({"run", scene.string(), "-o", out.string(), "--quiet"});
  ASSERT_EQ(second.exitCode, 0) << second.err;
  report = readJson(out / "report.json");
  for (const char* stage : {"simulate", "transfer", "synth"})
    EXPECT_TRUE(report["run"]["stages"][stage]["reused"].get<bool>()) << stage;

  { std::ofstream(scene) << std::string(kScene).replace(std::string(kScene).find("0.4,"), 4, "0.3,"); }
  CommandOutcome third = runFluidsound({"run", scene.string(), "-o", out.string(), "--quiet"});
  ASSERT_EQ(third.exitCode, 0) << third.err;
  report = readJson(out / "report.json");
  for (const char* stage : {"simulate", "transfer", "synth"})
    EXPECT_FALSE(report["run"]["stages"][stage]["reused"].get<bool>()) << stage << " after the scene changed";
}

/// A report without what differs from run to run: timings, memory, the files' paths.
nlohmann::json withoutTimings(nlohmann::json report) {
  report.erase("peak_memory_bytes");
  report.erase("stages");
  report["settings"].erase("input");
  report["settings"].erase("output");
  report["results"].erase("seconds");
  report["results"].erase("oscillator_samples_per_second");
  if (report["results"].contains("geometric")) report["results"]["geometric"].erase("solve_seconds");
  if (report["results"].contains("frames"))
    for (auto& frame : report["results"]["frames"]) frame.erase("seconds");
  return report;
}

// Claim (issue 18): `run` hands the bubble tracks from stage to stage in memory, and the bits are
// those of the three commands run one after the other through the files: the same bubbles.json,
// samples and reports (but for timings and paths), report.json being simulate's plus `run`.
// Reference: `simulate`, `transfer`, `synth` into another folder.
TEST(RunCommand, GivesTheBitsOfTheSingleStageCommands) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "fall.scene.json", staged = folder.path() / "staged",
                 run = folder.path() / "run";
  // The column's first 0.25 s (a few bubbles): four commands stay within a test's time.
  {
    std::ofstream(scene) << std::string(kScene).replace(std::string(kScene).find("0.4,"), 4,
                                                        "0.25,");
  }
  for (const std::initializer_list<std::string> command :
       {std::initializer_list<std::string>{"simulate", scene.string(), "-o", staged.string(),
                                           "--quiet"},
        {"transfer", scene.string(), "-o", staged.string(), "--quiet"},
        {"synth", (staged / "bubbles.json").string(), "-o", (staged / "fall.wav").string(),
         "--report", (staged / "synth.report.json").string(), "--quiet"},
        {"run", scene.string(), "-o", run.string(), "--quiet"}}) {
    const CommandOutcome outcome = runFluidsound(command);
    ASSERT_EQ(outcome.exitCode, 0) << *command.begin() << ": " << outcome.err;
  }
  const auto bytes = [](const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(run / "bubbles.json"), bytes(staged / "bubbles.json"));
  const io::AudioBuffer expected = io::readAudio(staged / "fall.wav");
  ASSERT_GT(expected.frameCount(), 0u);
  EXPECT_TRUE(io::readAudio(run / "fall.wav").channels == expected.channels);
  for (const char* report : {"transfer.report.json", "synth.report.json"})
    EXPECT_EQ(withoutTimings(readJson(run / report)), withoutTimings(readJson(staged / report)))
        << report;
  nlohmann::json runReport = readJson(run / "report.json");
  EXPECT_EQ(runReport["run"]["peak_pascals"],
            readJson(staged / "synth.report.json")["results"]["peak_pascals"]);
  runReport.erase("run");
  EXPECT_EQ(withoutTimings(runReport), withoutTimings(readJson(staged / "report.json")));
}

// Bad input stops `run` before any output: a typo in the scene names its JSON path, exit 3.
TEST(RunCommand, BadSceneWritesNothing) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "bad.json", out = folder.path() / "out";
  { std::ofstream(scene) << std::string(kScene).replace(std::string(kScene).find("\"fps\""), 5, "\"fsp\""); }
  const CommandOutcome result = runFluidsound({"run", scene.string(), "-o", out.string(), "--quiet"});
  EXPECT_EQ(result.exitCode, 3);
  EXPECT_NE(result.err.find("time.fsp"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace fluidsound::test
