// tests/tools/input_limits_test.cpp — the real `fluidsound` on inputs that would exhaust the
// machine or never end (docs/cli.md, "Inputs" and "Render size"): `-` reads standard input; a
// FIFO, device or folder given as an input is refused (exit 3) without blocking; a render too
// large for the machine is refused before allocation naming what sets its length; a file nested
// too deep or with a number out of range is exit 3, never 5. Each leaves no output behind.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "support/file_bytes.h"
#include "support/command_runner.h"
#include "support/temp_folder.h"

namespace fluidsound {
namespace {

namespace fs = std::filesystem;
using test::CommandOutcome;
using test::runFluidsound;
using test::shellQuoted;

constexpr int kExitUsage = 2, kExitBadInput = 3;  // docs/cli.md

constexpr const char* kOneBubble = R"({"format": "fluidsound.bubbles/1", "sample_rate": 48000,
  "bubbles": [{"radius": 0.001, "birth": 0.01}]})";

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

using test::fileBytes;

/// Runs `fluidsound ARGUMENTS < input` in `folder`; stdout is discarded.
CommandOutcome runWithStandardInput(const fs::path& folder, const std::string& arguments,
                                    const fs::path& input) {
  const fs::path err = folder / "stderr.txt";
  const std::string command = "cd " + shellQuoted(folder.string()) + " && " +
                              shellQuoted(FLUIDSOUND_EXECUTABLE) + " " + arguments + " < " +
                              shellQuoted(input.string()) + " > /dev/null 2> " +
                              shellQuoted(err.string());
  const int status = std::system(command.c_str());
  CommandOutcome outcome{WIFEXITED(status) ? WEXITSTATUS(status) : -1, fileBytes(err)};
  fs::remove(err);
  return outcome;
}

/// The outcome is exit `code` with exactly the line "fluidsound: error: MESSAGE".
void expectError(const CommandOutcome& outcome, int code, const std::string& message) {
  EXPECT_EQ(outcome.exitCode, code) << outcome.err;
  EXPECT_EQ(outcome.err, "fluidsound: error: " + message + "\n");
}

// Claim: `synth -` reads the bubble file from standard input and writes the same samples as from
// the file itself (reference: the render of the file by name; tolerance: none, bytes compared).
TEST(InputLimits, SynthReadsStandardInputAsTheFile) {
  const test::TempFolder folder;
  const fs::path in = folder.path() / "in.json";
  writeFile(in, kOneBubble);
  ASSERT_EQ(
      runFluidsound({"synth", in.string(), "-o", (folder.path() / "named.wav").string(), "-q"})
          .exitCode,
      0);
  const CommandOutcome piped = runWithStandardInput(folder.path(), "synth - -o piped.wav -q", in);
  ASSERT_EQ(piped.exitCode, 0) << piped.err;
  EXPECT_EQ(fileBytes(folder.path() / "piped.wav"), fileBytes(folder.path() / "named.wav"));
}

// Claim: an error in a piped bubble file names "standard input" and its field.
TEST(InputLimits, PipedBadBubbleFileIsNamedStandardInput) {
  const test::TempFolder folder;
  const fs::path in = folder.path() / "in.json";
  writeFile(in,
            R"({"format": "fluidsound.bubbles/1", "bubbles": [{"radius": 1e308, "birth": 0}]})");
  expectError(runWithStandardInput(folder.path(), "synth - -o out.wav", in), kExitBadInput,
              "standard input: bubbles[0].radius: expected a number from 1e-06 to 1 (metres), "
              "found 1e+308");
  EXPECT_FALSE(fs::exists(folder.path() / "out.wav"));
}

// Claim: `spectrogram -` reads the audio from standard input (a WAV written by synth).
TEST(InputLimits, SpectrogramReadsStandardInput) {
  const test::TempFolder folder;
  const fs::path in = folder.path() / "in.json";
  writeFile(in, kOneBubble);
  ASSERT_EQ(runFluidsound({"synth", in.string(), "-o", (folder.path() / "a.wav").string(), "-q"})
                .exitCode,
            0);
  const CommandOutcome piped =
      runWithStandardInput(folder.path(), "spectrogram - -o a.png -q", folder.path() / "a.wav");
  EXPECT_EQ(piped.exitCode, 0) << piped.err;
  EXPECT_GT(fs::file_size(folder.path() / "a.png"), 0u);
}

// Claim: a FIFO given as an input (bubble file, audio, scene) is refused at once, exit 3, without
// opening it (which would block without a writer); nothing is written.
TEST(InputLimits, FifoInputIsRefusedWithoutBlocking) {
  const test::TempFolder folder;
  const fs::path fifo = folder.path() / "in.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string out = (folder.path() / "out").string();
  const std::string message = fifo.string() + ": expected a readable file, found a FIFO";
  expectError(runFluidsound({"synth", fifo.string(), "-o", out + ".wav"}), kExitBadInput, message);
  expectError(runFluidsound({"spectrogram", fifo.string(), "-o", out + ".png"}), kExitBadInput,
              message);
  expectError(runFluidsound({"simulate", fifo.string(), "-o", out}), kExitBadInput, message);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"in.fifo"});
}

// Claim: a character device (made here with /dev/null's numbers 1:3, never the system's) and a
// folder are refused as inputs, exit 3. mknod needs root: skipped otherwise.
TEST(InputLimits, DeviceAndFolderInputsAreRefused) {
  const test::TempFolder folder;
  const fs::path sub = folder.path() / "sub";
  fs::create_directories(sub);
  expectError(runFluidsound({"synth", sub.string(), "-o", (folder.path() / "o.wav").string()}),
              kExitBadInput, sub.string() + ": expected a readable file, found a folder");
  if (::geteuid() != 0) GTEST_SKIP() << "mknod needs root";
  const fs::path device = folder.path() / "null";
  ASSERT_EQ(::mknod(device.c_str(), S_IFCHR | 0600, makedev(1, 3)), 0);
  expectError(runFluidsound({"synth", device.string(), "-o", (folder.path() / "o.wav").string()}),
              kExitBadInput,
              device.string() + ": expected a readable file, found a character device");
  EXPECT_FALSE(fs::exists(folder.path() / "o.wav"));
}

// Claim: a render beyond 2^31 samples is refused before allocation, naming what sets its length:
// the file's duration (exit 3), --duration (exit 2), or without a duration the bubble that rings
// last (exit 3). 100 000 s × 48 kHz = 4.8·10⁹ samples (it used to end in std::bad_alloc, exit 5).
TEST(InputLimits, RenderTooLargeIsRefusedNamingItsLength) {
  const test::TempFolder folder;
  const fs::path longFile = folder.path() / "long.json";
  writeFile(longFile,
            R"({"format": "fluidsound.bubbles/1", "sample_rate": 48000, "duration": 100000,
                          "bubbles": [{"radius": 0.001, "birth": 0.1}]})");
  const fs::path lateBubble = folder.path() / "late.json";
  writeFile(lateBubble, R"({"format": "fluidsound.bubbles/1", "sample_rate": 48000,
                            "bubbles": [{"radius": 0.001, "birth": 0.1}, {"radius": 0.001, "birth": 90000}]})");
  const std::string out = (folder.path() / "out.wav").string();
  const CommandOutcome fromFile = runFluidsound({"synth", longFile.string(), "-o", out});
  EXPECT_EQ(fromFile.exitCode, kExitBadInput) << fromFile.err;
  EXPECT_TRUE(
      fromFile.err.starts_with("fluidsound: error: " + longFile.string() +
                               ": duration: expected a render of at most 2.147e+09 samples"))
      << fromFile.err;
  EXPECT_NE(
      fromFile.err.find("found 100000 s × 48000 Hz × 1 channel = 4.8e+09 samples (35.8 GiB)\n"),
      std::string::npos)
      << fromFile.err;
  const CommandOutcome fromOption =
      runFluidsound({"synth", lateBubble.string(), "-o", out, "--duration", "1e5"});
  EXPECT_EQ(fromOption.exitCode, kExitUsage) << fromOption.err;
  EXPECT_TRUE(
      fromOption.err.starts_with("fluidsound: error: --duration: expected a render of at most"))
      << fromOption.err;
  const CommandOutcome fromBubble = runFluidsound({"synth", lateBubble.string(), "-o", out});
  EXPECT_EQ(fromBubble.exitCode, kExitBadInput) << fromBubble.err;
  EXPECT_TRUE(fromBubble.err.starts_with("fluidsound: error: " + lateBubble.string() +
                                         ": bubbles[1]: expected"))
      << fromBubble.err;
  EXPECT_EQ(std::count(fromBubble.err.begin(), fromBubble.err.end(), '\n'), 1) << fromBubble.err;
  EXPECT_EQ(folder.entries().size(), 2u) << "only the two inputs remain";
}

// Claim: a bubble file nested 100 000 levels deep (200 KB) is refused at level 65, exit 3, in
// well under a second and a few MB (it took > 16 GiB in the duplicate-key check's paths).
TEST(InputLimits, DeeplyNestedBubbleFileIsRefused) {
  const test::TempFolder folder;
  const fs::path deep = folder.path() / "deep.json";
  writeFile(deep, R"({"format": "fluidsound.bubbles/1", "x_deep": )" + std::string(100000, '[') +
                      std::string(100000, ']') + R"(, "bubbles": []})");
  const CommandOutcome outcome =
      runFluidsound({"synth", deep.string(), "-o", (folder.path() / "o.wav").string()});
  EXPECT_EQ(outcome.exitCode, kExitBadInput) << outcome.err;
  EXPECT_NE(
      outcome.err.find(": expected at most 64 nested arrays and objects, found a deeper array\n"),
      std::string::npos)
      << outcome.err;
  EXPECT_TRUE(outcome.err.starts_with("fluidsound: error: " + deep.string() + ": x_deep[0][0]"))
      << outcome.err;
}

}  // namespace
}  // namespace fluidsound
