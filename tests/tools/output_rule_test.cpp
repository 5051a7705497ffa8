// tests/tools/output_rule_test.cpp — every output of the real executable follows the output rule
// (docs/cli.md, "Outputs"): devices, FIFOs and `-` are written through, links keep standing,
// what cannot be written is refused before any work, an output never names an input or another
// output, and the format is never guessed.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/command_runner.h"
#include "support/spawned_command.h"
#include "support/special_files.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

/// Two bubbles, two listeners: renders in milliseconds.
const std::string kBubbles = R"({"format": "fluidsound.bubbles/1", "listeners": ["l", "r"], "bubbles": [
  {"radius": 0.001, "birth": 0.01}, {"radius": 0.002, "birth": 0.02}]})";

class OutputRule : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(input_) << kBubbles; }

  /// `synth IN ARGS… --quiet`
  CommandOutcome synth(std::initializer_list<std::string> arguments) {
    std::vector<std::string> all{"synth", input_.string()};
    all.insert(all.end(), arguments.begin(), arguments.end());
    all.push_back("--quiet");
    return runWords(all);
  }
  static CommandOutcome runWords(const std::vector<std::string>& words) {
    std::string command = shellQuoted(FLUIDSOUND_EXECUTABLE);
    for (const std::string& word : words) command.append(" ").append(shellQuoted(word));
    command += " 2>&1 >/dev/null";
    CommandOutcome outcome;
    std::FILE* pipe = ::popen(command.c_str(), "r");
    char buffer[4096];
    std::size_t count = 0;
    while ((count = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) outcome.err.append(buffer, count);
    const int status = ::pclose(pipe);
    outcome.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return outcome;
  }
  fs::path at(const std::string& name) const { return folder_.path() / name; }
  /// The folder holds exactly `names` (no temporary, no report of what failed).
  void expectEntries(std::vector<std::string> names) const {
    std::sort(names.begin(), names.end());
    EXPECT_EQ(folder_.entries(), names);
  }

  TempFolder folder_;
  fs::path input_ = folder_.path() / "in.json";
};

void expectOneLineError(const CommandOutcome& r, int exitCode, const std::string& part) {
  EXPECT_EQ(r.exitCode, exitCode) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST_F(OutputRule, NullDeviceIsWrittenThroughWithoutAReportBesideIt) {
  if (!makeCharacterDevice(at("null"), kMemoryMajor, kNullMinor)) GTEST_SKIP() << "mknod needs CAP_MKNOD";
  const CommandOutcome r = synth({"-o", at("null").string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_character_file(at("null")));
  expectEntries({"in.json", "null"});  // a stream has no default report
}

TEST_F(OutputRule, FullDeviceIsOneLineWriteErrorAndLeavesNothing) {
  if (!makeCharacterDevice(at("full"), kMemoryMajor, kFullMinor)) GTEST_SKIP() << "mknod needs CAP_MKNOD";
  const CommandOutcome r = synth({"-o", at("full").string(), "--report", at("report.json").string(),
                                  "--spectrogram", at("s.png").string()});
  expectOneLineError(r, 4, at("full").string() + ": cannot write: No space left on device");
  EXPECT_TRUE(fs::is_character_file(at("full")));
  expectEntries({"full", "in.json"});
}

TEST_F(OutputRule, FifoGetsTheSameBytesAsAFile) {
  ASSERT_TRUE(makeFifo(at("pipe")));
  ASSERT_EQ(synth({"-o", at("file.wav").string()}).exitCode, 0);
  FifoReader reader(at("pipe"));
  const CommandOutcome r = synth({"-o", at("pipe").string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(reader.bytes(), fileBytes(at("file.wav")));
  EXPECT_TRUE(fs::is_fifo(at("pipe")));
}

TEST_F(OutputRule, DashWritesTheAudioToStandardOutputAndNotesToStderr) {
  ASSERT_EQ(synth({"-o", at("file.flac").string()}).exitCode, 0);
  SpawnedFluidsound wav({"synth", input_.string(), "-o", "-"}, at("stdout.wav"), at("stderr.txt"));
  ASSERT_TRUE(wav.started());
  EXPECT_EQ(wav.wait(), 0) << wav.err();
  EXPECT_NE(wav.err().find("wrote standard output"), std::string::npos) << wav.err();
  EXPECT_EQ(fileBytes(at("stdout.wav")).substr(0, 4), "RIFF");  // default WAV
  SpawnedFluidsound flac({"synth", input_.string(), "-o", "-", "--format", "flac", "-q"}, at("stdout.flac"),
                         at("stderr.txt"));
  EXPECT_EQ(flac.wait(), 0) << flac.err();
  EXPECT_EQ(fileBytes(at("stdout.flac")), fileBytes(at("file.flac")));
  SpawnedFluidsound png({"spectrogram", at("file.flac").string(), "-o", "-", "-q"}, at("stdout.png"), at("stderr.txt"));
  EXPECT_EQ(png.wait(), 0) << png.err();
  EXPECT_EQ(fileBytes(at("stdout.png")).substr(0, 8), "\x89PNG\r\n\x1a\n");  // the PNG signature
}

TEST_F(OutputRule, LinkThroughProcIsWrittenThroughLikeDevStdout) {
  // /dev/stdout is a link to /proc/self/fd/1; the same link made here (never the system's /dev):
  // with stdout a regular file it must still be written through, with no report made beside it.
  fs::create_symlink("/proc/self/fd/1", at("stdout"));
  SpawnedFluidsound process({"synth", input_.string(), "-o", at("stdout").string(), "-q"}, at("captured.wav"),
                            at("stderr.txt"));
  EXPECT_EQ(process.wait(), 0) << process.err();
  EXPECT_EQ(fileBytes(at("captured.wav")).substr(0, 4), "RIFF");
  EXPECT_TRUE(fs::is_symlink(at("stdout")));
  expectEntries({"captured.wav", "in.json", "stderr.txt", "stdout"});
}

TEST_F(OutputRule, SymlinkKeepsStandingAndItsTargetIsReplaced) {
  std::ofstream(at("target.wav")) << "old";
  fs::create_symlink("target.wav", at("link.wav"));
  const CommandOutcome r = synth({"-o", at("link.wav").string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(at("link.wav")));
  EXPECT_EQ(fileBytes(at("target.wav")).substr(0, 4), "RIFF");
  expectEntries({"in.json", "link.wav", "link.wav.report.json", "target.wav"});
}

TEST_F(OutputRule, FolderSocketAndLinkToNothingAreRefusedBeforeWork) {
  fs::create_directory(at("dir.wav"));
  fs::create_symlink("nothing.wav", at("dangling.wav"));
  std::vector<std::string> names{"in.json", "dir.wav", "dangling.wav"};
  std::vector<std::pair<std::string, std::string>> cases{{"dir.wav", "it is a folder"},
                                                         {"dangling.wav", "symbolic link to nothing"}};
  if (makeSocketFile(at("sock.wav"))) {
    cases.emplace_back("sock.wav", "it is a socket");
    names.push_back("sock.wav");
  }
  for (const auto& [name, reason] : cases) {
    expectOneLineError(synth({"-o", at(name).string()}), 4, reason);
    expectOneLineError(synth({"-o", at("ok.wav").string(), "--report", at(name).string()}), 4, reason);
  }
  expectEntries(names);
}

TEST_F(OutputRule, AnOutputThatIsAnInputOrAnotherOutputIsAUsageError) {
  std::ofstream(at("old.wav")) << "old";
  fs::create_symlink("old.wav", at("alias.wav"));
  expectOneLineError(synth({"-o", input_.string(), "--format", "wav"}), 2, "bubbles and --output");
  expectOneLineError(synth({"-o", at("a.wav").string(), "--report", at("a.wav").string()}), 2,
                     "--output and --report");
  // An existing file through a link, and a new name through `..`.
  expectOneLineError(synth({"-o", at("old.wav").string(), "--spectrogram", at("alias.wav").string()}), 2,
                     "--output and --spectrogram");
  fs::create_directory(at("sub"));
  expectOneLineError(synth({"-o", at("n.wav").string(), "--report", at("r.json").string(), "--spectrogram",
                            (folder_.path() / "sub" / ".." / "r.json").string()}),
                     2, "--report and --spectrogram");
  EXPECT_EQ(fileBytes(at("old.wav")), "old");
  expectEntries({"alias.wav", "in.json", "old.wav", "sub"});
  SpawnedFluidsound spectrogram({"spectrogram", at("old.wav").string(), "-o", at("alias.wav").string()},
                                at("out.txt"), at("err.txt"));
  EXPECT_EQ(spectrogram.wait(), 2) << spectrogram.err();
  EXPECT_NE(spectrogram.err().find("audio and --output"), std::string::npos) << spectrogram.err();
}

TEST_F(OutputRule, FormatIsNeverGuessed) {
  expectOneLineError(synth({"-o", at("out.mp3").string()}), 2, "--output");
  expectOneLineError(synth({"-o", at("out").string()}), 2, "--output");
  expectOneLineError(synth({"-o", at("out.flac").string(), "--bits", "32"}), 2, "--bits");
  expectOneLineError(synth({"-o", at("out.wav").string(), "--format", "flac"}), 2, "--format and --output");
  expectEntries({"in.json"});
  EXPECT_EQ(synth({"-o", at("out").string(), "--format", "flac"}).exitCode, 0);  // said explicitly
  EXPECT_EQ(fileBytes(at("out")).substr(0, 4), "fLaC");
}

TEST_F(OutputRule, WavAndFlacOfOneNameKeepTheirOwnReports) {
  ASSERT_EQ(synth({"-o", at("out.wav").string()}).exitCode, 0);
  ASSERT_EQ(synth({"-o", at("out.flac").string(), "--bits", "16"}).exitCode, 0);
  expectEntries({"in.json", "out.flac", "out.flac.report.json", "out.wav", "out.wav.report.json"});
  EXPECT_NE(fileBytes(at("out.wav.report.json")).find("\"bits\": 32"), std::string::npos);
  EXPECT_NE(fileBytes(at("out.flac.report.json")).find("\"bits\": 16"), std::string::npos);
  EXPECT_NE(fileBytes(at("out.flac.report.json")).find("\"complete\": true"), std::string::npos);
}

TEST_F(OutputRule, NonUtf8OutputNameIsWrittenWithItsReport) {
  // Linux file names are bytes; the report is JSON (UTF-8): the name's invalid byte becomes U+FFFD
  // there, and the WAV is never left without its report.
  const std::string name = "\xff.wav";
  const CommandOutcome r = synth({"-o", at(name).string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(fileBytes(at(name)).substr(0, 4), "RIFF");
  EXPECT_NE(fileBytes(at(name + ".report.json")).find("\xef\xbf\xbd.wav"), std::string::npos);  // U+FFFD
}

}  // namespace
}  // namespace fluidsound::test
