// tests/tools/interruption_test.cpp — SIGINT and SIGTERM sent to a running `fluidsound simulate`,
// `run` and `synth`: one line naming the signal and where, exit 128 + signal, no temporary file,
// no bubbles.json (no audio for synth), and for simulate and run a report.json that says
// `"complete": false` (docs/cli.md, "Signals").
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "support/spawned_command.h"
#include "support/special_files.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

/// 150 frames of a small box of water: about 0.1 s a frame on one thread, so it is always
/// still running when the signal comes after frame 1 (the test ends at the signal).
const std::string kLongScene = R"({"format": "fluidsound.scene/1",
  "domain": {"min": [0, 0, 0], "max": [0.08, 0.08, 0.04], "cell": 0.01},
  "time": {"duration": 5, "fps": 30},
  "liquid": [{"box": {"min": [0, 0, 0], "max": [0.03, 0.06, 0.04]}}]})";

/// Every file under `folder` whose name starts with '.' (AtomicFile's temporaries).
std::vector<std::string> hiddenFiles(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.path().filename().string().starts_with(".")) names.push_back(entry.path().string());
  return names;
}

struct Interrupted {
  int exitCode = -1;
  std::string err;
};

/// Starts `fluidsound COMMAND scene -o out --threads 1`, waits for frame 1, sends `signalNumber`.
Interrupted interrupt(const TempFolder& folder, const std::string& command, int signalNumber) {
  const fs::path scene = folder.path() / "long.json";
  std::ofstream(scene) << kLongScene;
  SpawnedFluidsound process({command, scene.string(), "-o", (folder.path() / "out").string(), "--threads", "1"},
                            folder.path() / "stdout.txt", folder.path() / "stderr.txt");
  EXPECT_TRUE(process.started());
  EXPECT_TRUE(process.waitForStderr("frame    1/150", 20s)) << process.err();
  process.signal(signalNumber);
  Interrupted result;
  result.exitCode = process.wait();
  result.err = process.err();
  return result;
}

/// The last line of the stderr (the progress lines of frames come before it).
std::string lastLine(const std::string& text) {
  const std::string trimmed = text.substr(0, text.find_last_not_of('\n') + 1);
  return trimmed.substr(trimmed.find_last_of('\n') + 1);
}

int linesWith(const std::string& text, const std::string& part) {
  int count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

void expectIncompleteReport(const fs::path& out) {
  const nlohmann::json report = nlohmann::json::parse(fileBytes(out / "report.json"));
  EXPECT_EQ(report.at("complete"), false);
  EXPECT_TRUE(report.at("interrupted_at").get<std::string>().starts_with("simulate frame "));
  EXPECT_FALSE(fs::exists(out / "bubbles.json"));
  EXPECT_EQ(hiddenFiles(out), std::vector<std::string>{});
}

TEST(Interruption, SigintEndsSimulateWithOneLineAndAnIncompleteReport) {
  TempFolder folder;
  const Interrupted r = interrupt(folder, "simulate", SIGINT);
  EXPECT_EQ(r.exitCode, 130) << r.err;
  const std::string line = lastLine(r.err);
  EXPECT_TRUE(line.starts_with("fluidsound: interrupted (SIGINT) at simulate frame ")) << r.err;
  EXPECT_TRUE(line.ends_with("report.json marked incomplete")) << r.err;
  EXPECT_EQ(linesWith(r.err, "interrupted"), 1) << r.err;  // one line, nothing after the frames
  expectIncompleteReport(folder.path() / "out");
  // The frames on disk are whole: each one reported in the log was renamed into place.
  EXPECT_TRUE(fs::is_regular_file(folder.path() / "out" / "frames" / "0001.vdb"));
}

TEST(Interruption, SigtermEndsRunWithExit143AndNoStageRecorded) {
  TempFolder folder;
  const Interrupted r = interrupt(folder, "run", SIGTERM);
  EXPECT_EQ(r.exitCode, 143) << r.err;
  EXPECT_TRUE(lastLine(r.err).starts_with("fluidsound: interrupted (SIGTERM) at simulate frame ")) << r.err;
  const fs::path out = folder.path() / "out";
  expectIncompleteReport(out);
  // The simulate stage did not complete, so a later run does not reuse it.
  if (fs::exists(out / "stages.json")) {
    EXPECT_EQ(fileBytes(out / "stages.json").find("simulate"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(out / "long.wav"));
}

TEST(Interruption, SecondSignalStillLeavesNoTemporary) {
  // Two signals in a row: either the first ends the command normally, or the second removes the
  // registered temporaries and ends it at once; both exit 130 and leave no temporary.
  TempFolder folder;
  const fs::path scene = folder.path() / "long.json";
  std::ofstream(scene) << kLongScene;
  SpawnedFluidsound process({"simulate", scene.string(), "-o", (folder.path() / "out").string(), "--threads", "1"},
                            folder.path() / "stdout.txt", folder.path() / "stderr.txt");
  ASSERT_TRUE(process.waitForStderr("frame    1/150", 20s)) << process.err();
  process.signal(SIGINT);
  process.signal(SIGINT);
  EXPECT_EQ(process.wait(), 130) << process.err();
  EXPECT_NE(lastLine(process.err()).find("interrupted"), std::string::npos) << process.err();
  EXPECT_EQ(hiddenFiles(folder.path() / "out"), std::vector<std::string>{});
  EXPECT_FALSE(fs::exists(folder.path() / "out" / "bubbles.json"));
}

TEST(Interruption, SigtermEndsSynthWithNothingWritten) {
  // 100 000 bubbles over 200 s of stereo: about 3 s of rendering on one thread, so a signal
  // 0.3 s in always comes while it runs (reading the file takes about 0.1 s).
  TempFolder folder;
  const fs::path bubbles = folder.path() / "many.json";
  {
    std::ofstream out(bubbles);
    out << R"({"format": "fluidsound.bubbles/1", "listeners": ["l", "r"], "duration": 200, "bubbles": [)";
    for (int i = 0; i < 100000; ++i)
      out << (i ? "," : "") << R"({"radius": )" << 0.0005 + 0.002 * (i % 97) / 97.0 << R"(, "birth": )" << i * 0.002
          << "}";
    out << "]}";
  }
  SpawnedFluidsound process({"synth", bubbles.string(), "-o", (folder.path() / "o.wav").string(), "--spectrogram",
                             (folder.path() / "o.png").string(), "--threads", "1"},
                            folder.path() / "stdout.txt", folder.path() / "stderr.txt");
  ASSERT_TRUE(process.waitUntilHandling(30s));
  std::this_thread::sleep_for(300ms);
  process.signal(SIGTERM);
  EXPECT_EQ(process.wait(), 143) << process.err();
  EXPECT_TRUE(lastLine(process.err()).starts_with("fluidsound: interrupted (SIGTERM) at synth")) << process.err();
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"many.json", "stderr.txt", "stdout.txt"}));
}

TEST(Interruption, SigintEndsAWaitForAFifoReader) {
  // A FIFO nobody reads: the write waits for a reader, and the first signal still ends it.
  TempFolder folder;
  const fs::path bubbles = folder.path() / "in.json", fifo = folder.path() / "pipe";
  std::ofstream(bubbles) << R"({"format": "fluidsound.bubbles/1", "listeners": ["l"], "bubbles": [
    {"radius": 0.001, "birth": 0.01}]})";
  ASSERT_TRUE(makeFifo(fifo));
  SpawnedFluidsound process({"synth", bubbles.string(), "-o", fifo.string(), "-q"}, folder.path() / "stdout.txt",
                            folder.path() / "stderr.txt");
  // Signalled once it waits for the reader: its main thread sleeps between tries of open()
  // (clock_nanosleep, system call 230 on x86-64).
  ASSERT_TRUE(process.waitUntilHandling(30s, 230)) << "the command never waited for a FIFO reader";
  process.signal(SIGINT);
  EXPECT_EQ(process.wait(), 130) << process.err();
  EXPECT_EQ(lastLine(process.err()), "fluidsound: interrupted (SIGINT) at waiting for a reader of " + fifo.string());
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"in.json", "pipe", "stderr.txt", "stdout.txt"}));
}

}  // namespace
}  // namespace fluidsound::test
