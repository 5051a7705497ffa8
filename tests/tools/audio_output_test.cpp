// Tests of the audio output of `synth` and `run` through the real executable
// (tools/audio_options.h): both take the same audio options, reports state the scale, gain,
// loudness and true peak of what was written and the channels' listener names, and list every
// library's version as an object.
#include <embree3/rtcore_config.h>
#include <gtest/gtest.h>
#include <openvdb/version.h>

#include <Eigen/Core>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "io/loudness.h"
#include "acoustics/synthesis/oscillator_kernel.h"
#include "io/audio_file.h"
#include "support/command_runner.h"
#include "support/falling_column_scene.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(std::string(std::istreambuf_iterator<char>(in), {}));
}

/// Three listeners hear a few bubbles over 1.5 s.
constexpr const char* kThreeListeners = R"({"format": "fluidsound.bubbles/1", "sample_rate": 48000,
  "listeners": ["near", "far", "under & over"], "duration": 1.5, "bubbles": [
  {"radius": 0.001, "birth": 0.05, "track": [{"t": 0.05, "depth": 0.02, "transfer": [1, 0.5, 0.25]}]},
  {"radius": 0.002, "birth": 0.4, "track": [{"t": 0.4, "depth": 0.03, "transfer": [0.8, 0.4, 0.2]}]},
  {"radius": 0.0015, "birth": 0.9, "track": [{"t": 0.9, "depth": 0.02, "transfer": [0.6, 0.6, 0.3]}]},
  {"radius": 0.003, "birth": 1.2, "track": [{"t": 1.2, "depth": 0.04, "transfer": [1, 0.7, 0.5]}]}]})";

fs::path writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

io::LoudnessMeasurement measuredFile(const fs::path& path) {
  const io::AudioBuffer audio = io::readAudio(path);
  return io::measureLoudness(audio.channels, audio.sampleRate);
}

// Claim: synth and run take the same audio options, checked the same way (one helper): a ceiling
// without a target, a target with a peak normalisation and a target above 0 LUFS are command-line
// errors (exit 2, one line naming the option) before any output.
TEST(AudioOutput, SynthAndRunRefuseTheSameBadAudioOptions) {
  const TempFolder folder;
  const fs::path bubbles = writeText(folder.path() / "b.json", kThreeListeners);
  const fs::path scene = writeText(folder.path() / "s.scene.json", kFallingColumnScene);
  struct Bad {
    std::vector<std::string> options;
    const char* named;
  };
  const std::vector<Bad> bad = {{{"--true-peak", "-1"}, "--true-peak"},
                                {{"--loudness", "-23", "--normalize", "-1"}, "--loudness"},
                                {{"--loudness", "3"}, "--loudness"}};
  for (const Bad& b : bad) {
    for (const std::string& command : {std::string("synth"), std::string("run")}) {
      // Built by append: g++ 12 warns falsely (-Wrestrict, GCC bug 105329) on "literal" + string&&.
      std::string line = shellQuoted(FLUIDSOUND_EXECUTABLE);
      line.append(" ").append(command).append(" ");
      if (command == "synth")
        line.append(bubbles.string()).append(" -o ").append((folder.path() / "o.wav").string());
      else
        line.append(scene.string()).append(" -o ").append((folder.path() / "out").string());
      for (const std::string& o : b.options) line.append(" ").append(shellQuoted(o));
      line += " 2>&1 >/dev/null";
      std::FILE* pipe = ::popen(line.c_str(), "r");
      ASSERT_NE(pipe, nullptr);
      std::string err;
      char buffer[512];
      for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
        err.append(buffer, n);
      const int status = ::pclose(pipe);
      EXPECT_EQ(WEXITSTATUS(status), 2) << line << "\n" << err;
      EXPECT_NE(err.find(b.named), std::string::npos) << err;
      EXPECT_FALSE(fs::exists(folder.path() / "o.wav"));
      EXPECT_FALSE(fs::exists(folder.path() / "out"));
    }
  }
}

// Claim: by default the samples keep their calibrated pascals, and the report says so
// ("1.0 = 1 Pa = 94.0 dB SPL": 20·log10(1 Pa / 20 µPa) = 93.98 dB) with gain 1, the integrated
// loudness and true peak of the file as an independent meter reads it back (±0.01 LU: the same
// samples) and the listener names in channel order.
TEST(AudioOutput, SynthReportsTheCalibratedScaleLoudnessAndChannelNames) {
  const TempFolder folder;
  const fs::path bubbles = writeText(folder.path() / "b.json", kThreeListeners);
  const fs::path wav = folder.path() / "three.wav";
  const CommandOutcome r =
      runFluidsound({"synth", bubbles.string(), "-o", wav.string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json audio =
      readJson(folder.path() / "three.wav.report.json")["results"]["audio_output"];
  EXPECT_EQ(audio["scale"], "1.0 = 1 Pa = 94.0 dB SPL");
  EXPECT_EQ(audio["calibrated"], true);
  EXPECT_EQ(audio["gain"], 1.0);
  const io::LoudnessMeasurement m = measuredFile(wav);
  ASSERT_TRUE(m.integratedLufs.has_value());
  EXPECT_NEAR(audio["integrated_loudness_lufs"].get<double>(), *m.integratedLufs, 0.01);
  EXPECT_NEAR(audio["true_peak_dbtp"].get<double>(), m.truePeakDbtp, 0.01);
  EXPECT_EQ(audio["channels"], nlohmann::json::parse(R"(["near", "far", "under & over"])"));
}

// Claim (issue 20; docs/binaural.md): a listener that is a head gives two channels named after it,
// at 48 kHz through the KEMAR set resampled from 44.1 kHz; bubbles to its left are louder in its
// left ear; a bad `hrtf` is one line naming the bubble file and the field, and writes nothing.
TEST(AudioOutput, SynthRendersAHeadAsTwoNamedEars) {
  const TempFolder folder;
  const std::string text = R"({"format": "fluidsound.bubbles/1", "sample_rate": 48000, "duration": 1.0,
    "listeners": ["near", "ears"],
    "heads": [{"listener": "ears", "position": [0, 0, 0], "facing": [0, 0, 1], "up": [0, 1, 0]}],
    "bubbles": [
    {"radius": 0.001, "birth": 0.05, "track": [{"t": 0.05, "depth": 0.02, "transfer": [1, 0.5], "position": [2, 0, 0]}]},
    {"radius": 0.002, "birth": 0.4, "track": [{"t": 0.4, "depth": 0.03, "transfer": [0.8, 0.4], "position": [2, 0.1, 0]}]}]})";
  const fs::path bubbles = writeText(folder.path() / "b.json", text);
  const fs::path wav = folder.path() / "ears.wav";
  const CommandOutcome r = runFluidsound({"synth", bubbles.string(), "-o", wav.string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json audio = readJson(folder.path() / "ears.wav.report.json")["results"]["audio_output"];
  EXPECT_EQ(audio["channels"], nlohmann::json::parse(R"(["near", "ears.left", "ears.right"])"));
  const io::AudioBuffer written = io::readAudio(wav);
  ASSERT_EQ(written.channels.size(), 3u);
  EXPECT_EQ(written.sampleRate, 48000.0);
  const auto energy = [](const std::vector<float>& x) {
    double e = 0.0;
    for (float v : x) e += static_cast<double>(v) * v;
    return e;
  };
  EXPECT_GT(energy(written.channels[1]), 2.0 * energy(written.channels[2]));  // left ear, left side

  nlohmann::json bad = nlohmann::json::parse(text);
  bad["hrtf"] = "missing.sofa";
  const fs::path badFile = writeText(folder.path() / "bad.json", bad.dump());
  const fs::path badWav = folder.path() / "bad.wav";
  const CommandOutcome refused = runFluidsound({"synth", badFile.string(), "-o", badWav.string(), "--quiet"});
  EXPECT_NE(refused.exitCode, 0);
  EXPECT_NE(refused.err.find("bad.json: hrtf: expected a SOFA file"), std::string::npos) << refused.err;
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_FALSE(fs::exists(badWav));
}

// Claim (issue 17): synth's report names the oscillator kernel that ran, so its
// oscillator_samples_per_second says what it measured: the widest this CPU runs, as the
// synthesizer picks without being told (acoustics/synthesis/oscillator_kernel.h).
TEST(AudioOutput, SynthReportNamesTheOscillatorKernelThatRan) {
  const TempFolder folder;
  const fs::path bubbles = writeText(folder.path() / "b.json", kThreeListeners);
  const fs::path wav = folder.path() / "k.wav";
  const CommandOutcome r =
      runFluidsound({"synth", bubbles.string(), "-o", wav.string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json results = readJson(folder.path() / "k.wav.report.json")["results"];
  ASSERT_TRUE(results.contains("oscillator_kernel"));
  EXPECT_EQ(results["oscillator_kernel"].get<std::string>(),
            acoustics::oscillatorKernelName(acoustics::fastestOscillatorKernel()));
}

// Claim: --loudness L brings the file to L LUFS (EBU R 128 normalisation) unless the true peak
// would pass the --true-peak ceiling, in which case the gain stops at the ceiling and the report
// says so; the scale then names the pascals one full-scale unit stands for. Reference: the file
// measured back; tolerance ±0.1 LU and +0.2/−0.4 dBTP (EBU Tech 3341's meter requirements).
TEST(AudioOutput, SynthLoudnessTargetUnderATruePeakCeiling) {
  const TempFolder folder;
  const fs::path bubbles = writeText(folder.path() / "b.json", kThreeListeners);
  for (const double target : {-40.0, -10.0}) {
    const fs::path flac = folder.path() / "target.flac";
    const std::string targetText = std::to_string(target);
    const CommandOutcome r =
        runFluidsound({"synth", bubbles.string(), "-o", flac.string(), "--loudness", targetText,
                       "--true-peak", "-3", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json audio =
        readJson(folder.path() / "target.flac.report.json")["results"]["audio_output"];
    const io::LoudnessMeasurement m = measuredFile(flac);
    ASSERT_TRUE(m.integratedLufs.has_value());
    const bool limited = audio["true_peak_limited"].get<bool>();
    if (limited) {
      EXPECT_LT(*m.integratedLufs, target) << "limited, so short of the target";
      EXPECT_LE(m.truePeakDbtp, -3.0 + 0.2);
      EXPECT_GE(m.truePeakDbtp, -3.0 - 0.4);
    } else {
      EXPECT_NEAR(*m.integratedLufs, target, 0.1);
      EXPECT_LE(m.truePeakDbtp, -3.0 + 0.2);
    }
    EXPECT_EQ(limited, target == -10.0)
        << "a percussive render at -10 LUFS peaks above -3 dBTP; at -40 it does not";
    EXPECT_EQ(audio["calibrated"], false);
    char scale[64];
    std::snprintf(scale, sizeof scale, "1.0 = %.6g Pa", 1.0 / audio["gain"].get<double>());
    EXPECT_EQ(audio["scale"].get<std::string>().rfind(scale, 0), 0u) << audio["scale"];
  }
}

// Claim: run passes the audio options to its synth stage: --format flac writes NAME.flac at the
// loudness asked for, and a changed --loudness renders the audio again while the simulation and
// the transfer are reused.
TEST(AudioOutput, RunPassesTheAudioOptionsToItsSynthStage) {
  const TempFolder folder;
  const fs::path scene = writeText(folder.path() / "fall.scene.json", kFallingColumnScene);
  const fs::path out = folder.path() / "out";
  const auto run = [&](const char* loudness) {
    return runFluidsound({"run", scene.string(), "-o", out.string(), "--format", "flac", "--bits",
                          "16", "--loudness", loudness, "--true-peak", "-1", "--quiet"});
  };
  CommandOutcome first = run("-40");
  ASSERT_EQ(first.exitCode, 0) << first.err;
  EXPECT_TRUE(fs::is_regular_file(out / "fall.flac"));
  EXPECT_FALSE(fs::exists(out / "fall.wav"));
  nlohmann::json report = readJson(out / "report.json");
  EXPECT_EQ(report["run"]["audio"], "fall.flac");
  const io::LoudnessMeasurement m = measuredFile(out / "fall.flac");
  ASSERT_TRUE(m.integratedLufs.has_value());
  EXPECT_NEAR(report["run"]["audio_output"]["integrated_loudness_lufs"].get<double>(),
              *m.integratedLufs, 0.01);
  if (!report["run"]["audio_output"]["true_peak_limited"].get<bool>()) {
    EXPECT_NEAR(*m.integratedLufs, -40.0, 0.1);
  }
  EXPECT_EQ(io::readAudio(out / "fall.flac").channels.size(), 2u);

  CommandOutcome second = run("-42");
  ASSERT_EQ(second.exitCode, 0) << second.err;
  report = readJson(out / "report.json");
  EXPECT_TRUE(report["run"]["stages"]["simulate"]["reused"].get<bool>());
  EXPECT_TRUE(report["run"]["stages"]["transfer"]["reused"].get<bool>());
  EXPECT_FALSE(report["run"]["stages"]["synth"]["reused"].get<bool>())
      << "new --loudness, new audio";
  EXPECT_LT(*measuredFile(out / "fall.flac").integratedLufs, *m.integratedLufs - 1.5);
}

// Claim: report.json's `versions` is an object naming every library linked, each with the version
// its own header or runtime gives (here: the macros the tests are built with), and --version
// prints the same pairs.
TEST(AudioOutput, ReportAndVersionListEveryLibraryAsAnObject) {
  const TempFolder folder;
  const fs::path bubbles = writeText(folder.path() / "b.json", kThreeListeners);
  const CommandOutcome r = runFluidsound(
      {"synth", bubbles.string(), "-o", (folder.path() / "v.wav").string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json versions = readJson(folder.path() / "v.wav.report.json")["versions"];
  ASSERT_TRUE(versions.is_object()) << versions.dump();
  for (const char* name : {"fluidsound", "openvdb", "embree", "tbb", "eigen", "libsndfile",
                           "libebur128", "cairo", "nlohmann_json", "tinyobjloader", "cli11"}) {
    ASSERT_TRUE(versions.contains(name)) << name << " missing in " << versions.dump();
    EXPECT_FALSE(versions[name].get<std::string>().empty()) << name;
  }
  EXPECT_EQ(versions["openvdb"], OPENVDB_LIBRARY_VERSION_STRING);
  EXPECT_EQ(versions["embree"], RTC_VERSION_STRING);
  EXPECT_EQ(versions["eigen"], std::to_string(EIGEN_WORLD_VERSION) + "." +
                                   std::to_string(EIGEN_MAJOR_VERSION) + "." +
                                   std::to_string(EIGEN_MINOR_VERSION));
  EXPECT_EQ(versions["nlohmann_json"], std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                                           std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                                           std::to_string(NLOHMANN_JSON_VERSION_PATCH));
  EXPECT_EQ(versions["libebur128"], io::loudnessLibraryVersion());

  const fs::path text = folder.path() / "version.txt";
  ASSERT_EQ(std::system(
                (shellQuoted(FLUIDSOUND_EXECUTABLE) + " --version > " + shellQuoted(text.string()))
                    .c_str()),
            0);
  std::ifstream in(text);
  const std::string printed(std::istreambuf_iterator<char>(in), {});
  for (const auto& [name, version] : versions.items())
    EXPECT_NE(printed.find(name + " " + version.get<std::string>()), std::string::npos) << printed;
}

}  // namespace
}  // namespace fluidsound::test
