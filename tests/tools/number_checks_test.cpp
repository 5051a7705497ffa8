// Tests of tools/number_checks.h through the real executable: every floating-point option of every
// subcommand refuses NaN and ±infinity (CLI::Range let NaN through: `synth --normalize nan`,
// `spectrogram --range nan` and `validate --rate nan` ended in exit 5) with exit 2, one line naming
// the option, and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/command_runner.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

constexpr int kExitUsage = 2;

constexpr const char* kBubbles = R"({"format": "fluidsound.bubbles/1", "sample_rate": 48000,
  "duration": 0.2, "listeners": ["left"], "bubbles": [{"radius": 0.001, "birth": 0.01}]})";

/// One floating-point option, the command that takes it and what the message says it expects.
struct FloatOption {
  const char* command;   ///< synth, spectrogram or validate
  const char* option;    ///< e.g. "--normalize"
  const char* expected;  ///< the rule, as the message states it
  const char* needs;     ///< another option it needs ("" for none), given with `needsValue`
  const char* needsValue;
};

// One row per option, covering the three kinds: a range, > 0 and >= 0.
const std::vector<FloatOption> kFloatOptions = {
    {"synth", "--rate", "from 8000 to 768000", "", ""},
    {"synth", "--normalize", "from -120 to 0", "", ""},
    {"synth", "--loudness", "from -70 to 0", "", ""},
    {"synth", "--true-peak", "from -70 to 0", "--loudness", "-23"},
    {"synth", "--displacement", "> 0", "", ""},
    {"synth", "--chirp-rise", ">= 0", "", ""},
    {"spectrogram", "--range", "from 10 to 200", "", ""},
    {"synth", "--duration", "> 0", "", ""},
    {"spectrogram", "--min-frequency", "> 0", "", ""},
    {"validate", "--rate", "from 44100 to 192000", "", ""},
    {"validate", "--displacement", "> 0", "", ""},
    {"validate", "--chirp-rise", ">= 0", "", ""},
};

/// Runs COMMAND with OPTION VALUE (and the option it needs) on a small valid input.
CommandOutcome runWith(const FloatOption& row, const std::string& value, const fs::path& folder) {
  const std::string input = (folder / "b.json").string(), needs = row.needs, command = row.command;
  const std::string out = (folder / (command == "spectrogram" ? "o.png" : "o.wav")).string();
  if (command == "validate") return runFluidsound({"validate", "--quiet", row.option, value});
  if (!needs.empty())
    return runFluidsound(
        {command, input, "-o", out, "--quiet", needs, row.needsValue, row.option, value});
  return runFluidsound({command, input, "-o", out, "--quiet", row.option, value});
}

// Claim: NaN, +inf and -inf (spelled as strtod reads them, and 1e999, which overflows to inf) are
// refused for every floating-point option by the option's own check: exit 2 (not 5, not 3 from a
// later stage), the first line of stderr names the option and says what was expected and found,
// that is the only error line, and no output appears in the folder.
// Reference: the CLI rule of docs/cli.md (bad command line: exit 2, one line naming the option).
TEST(NumberChecks, EveryFloatingPointOptionRefusesNanAndInfinity) {
  const TempFolder folder;
  std::ofstream(folder.path() / "b.json") << kBubbles;
  for (const FloatOption& row : kFloatOptions) {
    for (const std::string value : {"nan", "NaN", "inf", "-inf", "1e999"}) {
      SCOPED_TRACE(std::string(row.command) + " " + row.option + " " + value);
      const CommandOutcome result = runWith(row, value, folder.path());
      EXPECT_EQ(result.exitCode, kExitUsage) << result.err;
      const std::string firstLine = result.err.substr(0, result.err.find('\n'));
      EXPECT_EQ(firstLine, std::string("fluidsound: error: ") + row.option +
                               ": expected a finite number " + row.expected + ", found " + value);
      EXPECT_EQ(result.err.find("error", firstLine.size()), std::string::npos) << result.err;
      EXPECT_EQ(folder.entries(), std::vector<std::string>{"b.json"});
    }
  }
}

// Claim: the checks still accept the ends of their ranges and refuse a finite value just outside,
// with the same message (the rule is the range, not only finiteness).
// Reference: the ranges of docs/cli.md.
TEST(NumberChecks, RangeEndsAreAcceptedAndValuesBeyondThemRefused) {
  const TempFolder folder;
  std::ofstream(folder.path() / "b.json") << kBubbles;
  const FloatOption normalize = kFloatOptions[1];
  EXPECT_EQ(runWith(normalize, "-120", folder.path()).exitCode, 0);
  EXPECT_EQ(runWith(normalize, "0", folder.path()).exitCode, 0);
  const CommandOutcome above = runWith(normalize, "0.001", folder.path());
  EXPECT_EQ(above.exitCode, kExitUsage);
  EXPECT_EQ(above.err.substr(0, above.err.find('\n')),
            "fluidsound: error: --normalize: expected a finite number from -120 to 0, found 0.001");
  const CommandOutcome zero = runWith(kFloatOptions[4], "0", folder.path());  // --displacement > 0
  EXPECT_EQ(zero.exitCode, kExitUsage);
  EXPECT_NE(zero.err.find("--displacement: expected a finite number > 0, found 0"),
            std::string::npos)
      << zero.err;
  EXPECT_EQ(runWith(kFloatOptions[5], "0", folder.path()).exitCode, 0);  // --chirp-rise >= 0
}

}  // namespace
}  // namespace fluidsound::test
