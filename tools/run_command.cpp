// tools/run_command.cpp — see run_command.h.
#include "tools/run_command.h"

#include <CLI/CLI.hpp>

#include "tools/cell_option.h"
#include "tools/run_pipeline.h"
#include "tools/transfer_choice.h"

namespace fluidsound::tools {

CLI::App* addRunCommand(CLI::App& app, RunOptions& o) {
  CLI::App* c = app.add_subcommand(
      "run", "the whole pipeline: simulate -> transfer -> synth, to NAME.wav, spectrogram.png and report.json");
  c->add_option("scene", o.scene, "scene file (fluidsound.scene/1)")->required();
  c->add_option("-o,--output", o.output, "output folder")->required();
  c->add_flag("--fresh", o.fresh, "run every stage again, even if its artefacts are up to date");
  addCellOption(*c, o.cell);
  addAudioOutputOptions(*c, o.audio);
  addTransferModelOption(*c, o.transfer);
  c->add_option("--solids", o.solids,
                "how the scene's bodies sound: modal (their modes) or samples (its collision_samples played back)")
      ->check(CLI::IsMember({"modal", "samples"}));
  addOscillatorModelOptions(*c, o.model);
  addCommonOptions(*c, o.common);
  return c;
}

int runRunCommand(const RunOptions& o) {
  RunPipeline(o).run();
  return kExitSuccess;
}

}  // namespace fluidsound::tools
