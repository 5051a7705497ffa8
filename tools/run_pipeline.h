// tools/run_pipeline.h — `run`'s three stages in one process: simulate → transfer → synth, the
// bubble tracks and reports handed from one to the next in memory, each stage skipped when
// stages.json shows it up to date (tools/stage_records.h; its artefacts are then read back), and
// report.json written last: simulate's report plus the `run` summary.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "io/interruption.h"
#include "sim/scene.h"
#include "tools/run_command.h"
#include "tools/stage_records.h"

namespace fluidsound::tools {

class RunPipeline {
 public:
  /// Reads the scene and checks, before any output, what a later stage would refuse.
  /// @throws io::InputError, io::OutputError, CLI::ValidationError
  explicit RunPipeline(const RunOptions& options);

  /// Runs (or reuses) the stages and writes report.json. After a signal in a stage, report.json
  /// says `"complete": false` and where the run stopped (simulate marks its own).
  /// @throws io::Interrupted, and what the stages throw
  void run();

 private:
  /// One stage as stages.json records it: the files it reads and writes (relative to OUTDIR) and
  /// its input hash: the scene's, for transfer also the oscillator model (it gives ω) and the
  /// transfer model with its settings (--transfer may override the scene's), for synth the
  /// oscillator model and the audio options.
  struct StagePlan {
    const char* name;
    std::vector<std::string> reads, artefacts;
    std::string inputHash;
  };
  /// Runs `body` unless the stage's record shows it complete (same inputs, the files it reads as
  /// their producer left them, every artefact present and unchanged), then records what it read
  /// and wrote, so that an interrupted or damaged run redoes exactly the stages it must.
  /// @return whether it ran
  bool runStage(const StagePlan& plan, const std::function<void()>& body);

  void simulate();
  void transfer();
  void synth();
  void writeReport();
  /// The run's report so far marked incomplete at the signal's place, written to report.json.
  io::Interrupted markIncomplete(const io::Interrupted& signal);

  using Clock = std::chrono::steady_clock;
  const RunOptions& o_;
  Clock::time_point start_;
  sim::Scene scene_;
  std::string hash_, modelHash_, transferHash_, audioFile_;
  std::filesystem::path out_;
  std::vector<std::string> frames_;
  StageRecords records_;
  nlohmann::ordered_json stages_ = nlohmann::ordered_json::object();
  /// simulate's report.json: the base of the run's (a reused simulation keeps its own).
  nlohmann::ordered_json report_;
  /// The latest stage's tracks, while they are in memory; none after a reused stage, whose
  /// bubbles.json is then read.
  std::optional<acoustics::BubbleTrackSet> tracks_;
  nlohmann::ordered_json transferReport_, synthReport_;
};

}  // namespace fluidsound::tools
