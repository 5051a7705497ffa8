// Tests of the `fluidsound` command line: bad input gives one line naming the file, the JSON path
// and what was expected, a non-zero exit and no output file; good input gives audio and a report.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int exitCode = -1;
  std::string err;
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("fluidsound_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = folder_ / name;
    std::ofstream(p) << text;
    return p;
  }

  Outcome run(const std::string& arguments) {
    const fs::path errFile = folder_ / "stderr.txt";
    const std::string command = std::string(FLUIDSOUND_EXECUTABLE) + " " + arguments + " 2> " + errFile.string() + " > /dev/null";
    const int status = std::system(command.c_str());
    Outcome r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::stringstream text;
    text << std::ifstream(errFile).rdbuf();
    r.err = text.str();
    fs::remove(errFile);
    return r;
  }

  /// Only the inputs remain: no output, no temporary file.
  void expectNoOutput(const std::vector<std::string>& inputs) {
    for (const auto& entry : fs::directory_iterator(folder_)) {
      const std::string name = entry.path().filename().string();
      EXPECT_NE(std::find(inputs.begin(), inputs.end(), name), inputs.end()) << "left behind: " << name;
    }
  }

  /// Runs synth on `json` and checks a one-line error naming the file, `field` and `expected`.
  void expectBadBubbles(const std::string& json, const std::string& field, const std::string& expected) {
    const fs::path in = write("bad.json", json);
    const Outcome r = run("synth " + in.string() + " -o " + (folder_ / "out.wav").string());
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
    EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(field), std::string::npos) << "no field '" << field << "' in: " << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << "no '" << expected << "' in: " << r.err;
    expectNoOutput({"bad.json"});
  }

  fs::path folder_;
};

const std::string kHead = R"({"format": "fluidsound.bubbles/1", "listeners": ["l", "r"], "bubbles": [)";

TEST_F(Cli, MalformedJsonIsRejected) { expectBadBubbles(R"({"format": "fluidsound.bubbles/1", "bubbles": [}])", "bad.json", "expected valid JSON"); }
TEST_F(Cli, TruncatedJsonIsRejected) { expectBadBubbles(kHead + R"({"radius": 0.001, "bi)", "bad.json", "expected valid JSON"); }
TEST_F(Cli, WrongFormatTagIsRejected) { expectBadBubbles(R"({"format": "fluidsound.bubbles/9", "bubbles": []})", "format", "fluidsound.bubbles/1"); }
TEST_F(Cli, NegativeRadiusIsRejected) { expectBadBubbles(kHead + R"({"radius": -0.001, "birth": 0}]})", "bubbles[0].radius", "expected"); }
TEST_F(Cli, NonNumericRadiusIsRejected) { expectBadBubbles(kHead + R"({"radius": 0.001, "birth": 0}, {"radius": "big", "birth": 0}]})", "bubbles[1].radius", "expected"); }
TEST_F(Cli, MissingBirthIsRejected) { expectBadBubbles(kHead + R"({"radius": 0.001}]})", "bubbles[0].birth", "expected"); }
TEST_F(Cli, DepthNotBelowRadiusIsRejected) {
  expectBadBubbles(kHead + R"({"radius": 0.002, "birth": 0, "track": [{"t": 0, "depth": 0.001, "transfer": [1, 1]}]}]})",
                   "bubbles[0].track[0].depth", "expected");
}
TEST_F(Cli, UnsortedTrackIsRejected) {
  expectBadBubbles(kHead + R"({"radius": 0.001, "birth": 0, "track": [{"t": 0.1, "depth": 0.01, "transfer": [1, 1]},
                                                                     {"t": 0.05, "depth": 0.01, "transfer": [1, 1]}]}]})",
                   "bubbles[0].track[1].t", "expected");
}
TEST_F(Cli, WrongTransferLengthIsRejected) {
  expectBadBubbles(kHead + R"({"radius": 0.001, "birth": 0, "track": [{"t": 0, "depth": 0.01, "transfer": [1]}]}]})",
                   "bubbles[0].track[0].transfer", "expected");
}
TEST_F(Cli, UnknownKeyIsRejected) { expectBadBubbles(kHead + R"({"radius": 0.001, "birht": 0}]})", "bubbles[0].birht", "birth"); }

TEST_F(Cli, MissingFileIsRejected) {
  const Outcome r = run("synth " + (folder_ / "absent.json").string() + " -o " + (folder_ / "out.wav").string());
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("absent.json"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  expectNoOutput({});
}

TEST_F(Cli, UnwritableOutputIsRejectedBeforeRendering) {
  const fs::path in = write("ok.json", kHead + R"({"radius": 0.001, "birth": 0}]})");
  const Outcome r = run("synth " + in.string() + " -o " + (folder_ / "no" / "such" / "out.wav").string());
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_NE(r.err.find("out.wav"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  expectNoOutput({"ok.json"});
}

TEST_F(Cli, BadOptionIsAUsageError) {
  const fs::path in = write("ok.json", kHead + R"({"radius": 0.001, "birth": 0}]})");
  const Outcome r = run("synth " + in.string() + " -o " + (folder_ / "out.wav").string() + " --bits 12");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--bits"), std::string::npos) << r.err;
  expectNoOutput({"ok.json"});
}

// A good file renders to a stereo WAV, its report and its spectrogram; then `spectrogram` draws
// any audio file.
TEST_F(Cli, SynthWritesAudioReportAndSpectrogram) {
  const fs::path in = write("ok.json", kHead + R"({"radius": 0.001, "birth": 0.01, "track": [{"t": 0.01, "depth": 0.02, "transfer": [1, 0.5]}]},
                                                  {"radius": 0.002, "birth": 0.02}]})");
  const Outcome r = run("synth " + in.string() + " -o " + (folder_ / "out.wav").string() + " --spectrogram " +
                    (folder_ / "out.png").string() + " --quiet");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(folder_ / "out.wav"));
  EXPECT_TRUE(fs::exists(folder_ / "out.wav.report.json"));
  EXPECT_TRUE(fs::exists(folder_ / "out.png"));
  const Outcome s = run("spectrogram " + (folder_ / "out.wav").string() + " -o " + (folder_ / "again.png").string() +
                    " --log-frequency --quiet");
  EXPECT_EQ(s.exitCode, 0) << s.err;
  EXPECT_TRUE(fs::exists(folder_ / "again.png"));
}

TEST_F(Cli, VersionNamesTheLibraries) {
  const fs::path out = folder_ / "version.txt";
  const int status = std::system((std::string(FLUIDSOUND_EXECUTABLE) + " --version > " + out.string()).c_str());
  EXPECT_EQ(WEXITSTATUS(status), 0);
  std::stringstream text;
  text << std::ifstream(out).rdbuf();
  for (const char* name : {"fluidsound", "openvdb", "embree", "tbb", "eigen", "cli11", "libsndfile",
                           "libebur128", "cairo", "nlohmann_json", "tinyobjloader"})
    EXPECT_NE(text.str().find(name), std::string::npos) << name << " missing in: " << text.str();
}


const std::string kTinyScene = R"({"format": "fluidsound.scene/1",
  "domain": {"min": [0, 0, 0], "max": [0.08, 0.08, 0.04], "cell": 0.01},
  "time": {"duration": 0.1, "fps": 30},
  "liquid": [{"box": {"min": [0, 0, 0], "max": [0.03, 0.06, 0.04]}}]})";

// A scene simulates to frames/0000.vdb … and report.json (frame 0 is the initial state).
TEST_F(Cli, SimulateWritesFramesAndReport) {
  const fs::path scene = write("tiny.json", kTinyScene);
  const fs::path out = folder_ / "out";
  const Outcome r = run("simulate " + scene.string() + " -o " + out.string() + " --ply --quiet");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"0000.vdb", "0001.vdb", "0002.vdb", "0003.vdb", "0000.ply", "0003.ply"})
    EXPECT_TRUE(fs::exists(out / "frames" / name)) << name;
  EXPECT_FALSE(fs::exists(out / "frames" / "0004.vdb"));
  EXPECT_TRUE(fs::exists(out / "report.json"));
}

// A bad scene: one line naming the file and the JSON path, exit 3, and no output folder at all.
TEST_F(Cli, SimulateRejectsBadSceneBeforeWritingAnything) {
  std::string text = kTinyScene;
  text.replace(text.find("\"cell\""), 6, "\"cel\"");
  const fs::path scene = write("typo.json", text);
  const Outcome r = run("simulate " + scene.string() + " -o " + (folder_ / "out").string());
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("typo.json: domain.cel"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  expectNoOutput({"typo.json"});
}

// An output folder that cannot be made (a file stands in its way): exit 4, no frame written.
TEST_F(Cli, SimulateRejectsUnwritableOutput) {
  const fs::path scene = write("tiny.json", kTinyScene);
  write("blocked", "a file, not a folder");
  const Outcome r = run("simulate " + scene.string() + " -o " + (folder_ / "blocked").string());
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_NE(r.err.find("blocked"), std::string::npos) << r.err;
  expectNoOutput({"tiny.json", "blocked"});
}

}  // namespace
