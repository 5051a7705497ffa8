// tools/transfer_command.h — `fluidsound transfer SCENE.json -o OUTDIR`: fills the `transfer`
// values of OUTDIR/bubbles.json from the artefacts alone (frames/NNNN.vdb, the scene's listeners),
// with the image-source model; the stage itself is acoustics::computeTransfer
// (acoustics/transfer/transfer_stage.h; docs/transfer.md), this command only wires files to it.
#pragma once

#include <string>

#include "acoustics/bubble/oscillator_model.h"
#include "tools/command_options.h"

namespace fluidsound::tools {

struct TransferOptions {
  CommonOptions common;
  std::string scene;
  std::string output;
  acoustics::OscillatorModel model;  ///< gives each bubble's ω (the model synth renders with)
};

CLI::App* addTransferCommand(CLI::App& app, TransferOptions& options);
int runTransferCommand(const TransferOptions& options);

}  // namespace fluidsound::tools
