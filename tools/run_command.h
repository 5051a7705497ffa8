// tools/run_command.h — `fluidsound run SCENE.json -o OUTDIR`: the whole pipeline, simulate →
// transfer → synth, to OUTDIR/NAME.wav, OUTDIR/spectrogram.png and OUTDIR/report.json, reusing the
// artefacts of every stage whose inputs have not changed (so an interrupted run resumes).
#pragma once

#include <optional>
#include <string>

#include "acoustics/bubble/oscillator_model.h"
#include "sim/scene.h"
#include "tools/audio_options.h"
#include "tools/command_options.h"

namespace fluidsound::tools {

struct RunOptions {
  CommonOptions common;
  std::string scene;
  std::string output;
  bool fresh = false;  ///< run every stage even if its artefacts are up to date
  std::optional<double> cell;  ///< --cell: grid cell size [m] replacing domain.cell
  AudioOutputOptions audio;    ///< synth's audio options, passed on to the synth stage
  acoustics::OscillatorModel model;  ///< the run's one model: transfer's ω, synth's oscillators
  std::optional<sim::TransferModel> transfer;  ///< --transfer; empty: the scene's transfer.model
  /// --solids: how the bodies sound: "modal" (their modes) or "samples" (the scene's
  /// collision_samples played back, the baseline: docs/solids.md)
  std::string solids = "modal";
};

CLI::App* addRunCommand(CLI::App& app, RunOptions& options);
int runRunCommand(const RunOptions& options);

}  // namespace fluidsound::tools
