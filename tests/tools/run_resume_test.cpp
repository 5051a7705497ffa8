// Tests of `fluidsound run` resuming from what an earlier run left (issue 16 §4, §5): a stage is
// reused only when stages.json records it complete with the same inputs, the files it read as
// their producer left them, and every artefact present and unchanged (tools/stage_records.h).
// After a truncated WAV, a deleted frame, an edited bubbles.json or a simulate killed part-way,
// `run` re-runs exactly the stages that must run and ends with the same samples as a run that was
// never disturbed. All on the falling-column scene (12 frames, about a second per run).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <thread>

#include "io/audio_file.h"
#include "support/file_bytes.h"
#include "support/command_runner.h"
#include "support/falling_column_scene.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

nlohmann::json runStages(const fs::path& out) {
  return nlohmann::json::parse(fileBytes(out / "report.json"))["run"]["stages"];
}

/// One undisturbed run of the scene, shared by the tests (made once: each test copies it).
class RunResume : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() /
            ("fluidsound-RunResume-" + std::to_string(std::random_device{}()));
    fs::create_directories(root_);
    std::ofstream(root_ / "fall.scene.json") << kFallingColumnScene;
    reference_ = runFluidsound({"run", scene().string(), "-o", reference().string(), "--quiet"});
  }
  static void TearDownTestSuite() {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  void SetUp() override { ASSERT_EQ(reference_.exitCode, 0) << reference_.err; }

  static fs::path scene() { return root_ / "fall.scene.json"; }
  static fs::path reference() { return root_ / "reference"; }

  /// A copy of the undisturbed run's folder in `folder`.
  static fs::path copyOfReference(const TempFolder& folder) {
    const fs::path out = folder.path() / "out";
    fs::copy(reference(), out, fs::copy_options::recursive);
    return out;
  }

  static CommandOutcome run(const fs::path& out) {
    return runFluidsound({"run", scene().string(), "-o", out.string()});
  }

  /// Which stages re-ran, as the run's report says, e.g. "simulate transfer".
  static std::string stagesRun(const fs::path& out) {
    const nlohmann::json stages = runStages(out);
    std::string ran;
    for (const char* stage : {"simulate", "transfer", "synth"})
      if (!stages[stage]["reused"].get<bool>()) ran.append(ran.empty() ? "" : " ").append(stage);
    return ran;
  }

  /// The WAV is sample for sample the undisturbed run's (float WAVs carry a PEAK chunk with a
  /// time stamp, so samples are compared, not bytes).
  static void expectReferenceSamples(const fs::path& out) {
    const io::AudioBuffer expected = io::readAudio(reference() / "fall.wav");
    const io::AudioBuffer actual = io::readAudio(out / "fall.wav");
    ASSERT_EQ(actual.channels.size(), 2u);
    EXPECT_GT(expected.frameCount(), 0u);
    EXPECT_TRUE(actual.channels == expected.channels) << "samples differ from the undisturbed run";
  }

  /// After a resume, the folder is intact again: one more run reuses every stage.
  static void expectSettled(const fs::path& out) {
    const CommandOutcome again = run(out);
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(stagesRun(out), "") << "the run after the resume: " << again.err;
  }

  static fs::path root_;
  static CommandOutcome reference_;
};

fs::path RunResume::root_;
CommandOutcome RunResume::reference_;

// The control: an undisturbed folder reuses all three stages and its WAV is not rewritten.
TEST_F(RunResume, AnIntactFolderReusesEveryStage) {
  const TempFolder folder;
  const fs::path out = copyOfReference(folder);
  const CommandOutcome r = run(out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(stagesRun(out), "") << r.err;
  EXPECT_EQ(fileBytes(out / "fall.wav"), fileBytes(reference() / "fall.wav"));
}

// A truncated WAV was "up to date, reused". Only synth made it, so only synth runs again.
TEST_F(RunResume, ATruncatedWavIsRenderedAgain) {
  const TempFolder folder;
  const fs::path out = copyOfReference(folder);
  fs::resize_file(out / "fall.wav", fs::file_size(out / "fall.wav") / 2);
  const CommandOutcome r = run(out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(stagesRun(out), "synth") << r.err;
  EXPECT_NE(r.err.find("run: synth (fall.wav changed: "), std::string::npos) << r.err;
  expectReferenceSamples(out);
  expectSettled(out);
}

// A deleted frame was "up to date, reused". Frames are simulate's, so it runs again, and then
// transfer (simulate rewrote the bubbles.json transfer had filled). Synth is reused: the
// bubbles.json transfer writes again is byte for byte the one synth rendered from.
TEST_F(RunResume, ADeletedFrameIsSimulatedAgain) {
  const TempFolder folder;
  const fs::path out = copyOfReference(folder);
  fs::remove(out / "frames" / "0003.vdb");
  const CommandOutcome r = run(out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(stagesRun(out), "simulate transfer") << r.err;
  EXPECT_NE(r.err.find("run: simulate (frames/0003.vdb is missing)"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_regular_file(out / "frames" / "0003.vdb"));
  EXPECT_EQ(fileBytes(out / "bubbles.json"), fileBytes(reference() / "bubbles.json"));
  expectReferenceSamples(out);
  expectSettled(out);
}

// An edited bubbles.json was "up to date, reused". It is neither the file simulate wrote nor the
// one transfer wrote from it, and only simulate can make the positions and depths transfer needs:
// simulate and transfer run again, and synth, whose input is then again what it rendered, not.
TEST_F(RunResume, AnEditedBubbleFileIsSimulatedAgain) {
  const TempFolder folder;
  const fs::path out = copyOfReference(folder);
  std::string bubbles = fileBytes(out / "bubbles.json");
  const std::size_t radius = bubbles.find("\"radius\":");
  ASSERT_NE(radius, std::string::npos);
  bubbles.replace(radius, 9, std::string("\"radius\":1"));  // 0.00… m becomes 10.00… m
  std::ofstream(out / "bubbles.json", std::ios::binary) << bubbles;
  const CommandOutcome r = run(out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(stagesRun(out), "simulate transfer") << r.err;
  EXPECT_NE(r.err.find("run: simulate (bubbles.json changed: "), std::string::npos) << r.err;
  EXPECT_EQ(fileBytes(out / "bubbles.json"), fileBytes(reference() / "bubbles.json"));
  expectReferenceSamples(out);
  expectSettled(out);
}

// transfer.report.json changed: transfer runs again, on the bubbles.json it filled before (it
// recomputes every transfer value from simulate's positions), and writes the same bytes; synth is
// reused, and so is everything the time after (the record of what transfer read is simulate's
// version, not its own earlier output, which would have made simulate look changed).
TEST_F(RunResume, AChangedTransferReportRunsTransferOnce) {
  const TempFolder folder;
  const fs::path out = copyOfReference(folder);
  std::ofstream(out / "transfer.report.json", std::ios::app) << "\n";
  const CommandOutcome r = run(out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(stagesRun(out), "transfer") << r.err;
  EXPECT_EQ(fileBytes(out / "bubbles.json"), fileBytes(reference() / "bubbles.json"));
  expectSettled(out);
}

// stages.json is only trusted for what it records: one of another shape (a number as its format)
// counts as no record, and a record that does not list an artefact the stage writes is not taken
// to cover it; neither ends in an internal error.
TEST_F(RunResume, ADamagedStageRecordIsNotTrusted) {
  const TempFolder folder;
  const fs::path out = copyOfReference(folder);
  std::ofstream(out / "stages.json") << R"({"format": 5, "stages": []})";
  CommandOutcome r = run(out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(stagesRun(out), "simulate transfer synth") << r.err;

  nlohmann::json stages = nlohmann::json::parse(fileBytes(out / "stages.json"));
  stages["stages"]["simulate"]["artefacts"].erase("frames/0007.vdb");
  std::ofstream(out / "stages.json") << stages.dump();
  fs::remove(out / "frames" / "0007.vdb");
  r = run(out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(stagesRun(out), "simulate transfer") << r.err;
  EXPECT_NE(r.err.find("run: simulate (its record does not list frames/0007.vdb)"),
            std::string::npos)
      << r.err;
  expectReferenceSamples(out);
}

/// Starts `fluidsound run SCENE -o OUT --quiet` and kills it (SIGKILL) once frame `k` is on disk.
/// @return whether it was killed (false if it ended first)
bool killRunAtFrame(const fs::path& scene, const fs::path& out, int k) {
  char frame[32];
  std::snprintf(frame, sizeof frame, "%04d.vdb", k);
  const pid_t child = ::fork();
  if (child == 0) {
    ::execl(FLUIDSOUND_EXECUTABLE, FLUIDSOUND_EXECUTABLE, "run", scene.c_str(), "-o", out.c_str(),
            "--quiet", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(out / "frames" / frame) && std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(child, &status, WNOHANG) == child) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ::kill(child, SIGKILL);
  ::waitpid(child, &status, 0);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

// A simulate killed after frame 5 of 12 leaves frames 0 … 5 (perhaps a hidden temporary of
// frame 6) and no record that it completed. The next run simulates again (clearing the dead
// process's temporaries), then transfers and renders, to the undisturbed run's samples.
TEST_F(RunResume, ASimulateKilledPartWayIsRunAgain) {
  const TempFolder folder;
  const fs::path out = folder.path() / "out";
  ASSERT_TRUE(killRunAtFrame(scene(), out, 5));
  ASSERT_FALSE(fs::exists(out / "frames" / "0012.vdb"))
      << "killed too late to test a part-way simulation";
  EXPECT_FALSE(fs::exists(out / "bubbles.json"));
  EXPECT_FALSE(fs::exists(out / "stages.json"));
  const CommandOutcome r = run(out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(stagesRun(out), "simulate transfer synth") << r.err;
  std::size_t frames = 0;
  for (const auto& entry : fs::directory_iterator(out / "frames")) {
    EXPECT_NE(entry.path().filename().string()[0], '.') << "left: " << entry.path();
    ++frames;
  }
  EXPECT_EQ(frames, 13u);
  expectReferenceSamples(out);
  expectSettled(out);
}

// Everything run needs is checked before the first frame: 17 listeners (one more than the
// synthesizer's channels) failed in synth after a full simulation and transfer; a folder where
// the spectrogram goes failed after the render. Both now stop before OUTDIR/frames exists.
TEST_F(RunResume, WhatALaterStageWouldRefuseStopsTheRunBeforeTheFirstFrame) {
  const TempFolder folder;
  nlohmann::json scene = nlohmann::json::parse(kFallingColumnScene);
  scene["listeners"] = nlohmann::json::array();
  for (int i = 0; i < 17; ++i) {
    std::string name = "listener ";
    name.append(std::to_string(i));
    scene["listeners"].push_back({{"name", name}, {"position", {0.1, 0.4, 0.02}}});
  }
  const fs::path many = folder.path() / "many.scene.json", out = folder.path() / "out";
  std::ofstream(many) << scene.dump(2);
  CommandOutcome r = runFluidsound({"run", many.string(), "-o", out.string(), "--quiet"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_EQ(
      r.err,
      "fluidsound: error: " + many.string() +
          ": listeners: expected at most 16 listeners (one channel each), found 17 listeners\n");
  EXPECT_FALSE(fs::exists(out));

  fs::create_directories(out / "spectrogram.png");
  r = runFluidsound({"run", RunResume::scene().string(), "-o", out.string(), "--quiet"});
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_NE(r.err.find("spectrogram.png: cannot write: it is a folder"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out / "frames"));
}

}  // namespace
}  // namespace fluidsound::test
