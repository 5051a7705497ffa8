// tools/transfer_command.h — `fluidsound transfer SCENE.json -o OUTDIR`: fills the `transfer`
// values of OUTDIR/bubbles.json from the artefacts alone (frames/NNNN.vdb, the scene's listeners),
// with the image-source model; the stage itself is acoustics::computeTransfer
// (acoustics/transfer/transfer_stage.h; docs/transfer.md), this command only wires files to it.
#pragma once

#include <optional>
#include <string>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/bubble/oscillator_model.h"
#include "sim/scene.h"
#include "tools/command_options.h"

namespace fluidsound::tools {

struct TransferOptions {
  CommonOptions common;
  std::string scene;
  std::string output;
  acoustics::OscillatorModel model;  ///< gives each bubble's ω (the model synth renders with)
};

CLI::App* addTransferCommand(CLI::App& app, TransferOptions& options);

/// @brief The transfer stage in OUTDIR (options.output): fills the transfer values of `tracks`
///        (the simulation's, handed over in memory by `run`; none: read from OUTDIR/bubbles.json
///        and checked against the scene's listeners) for `scene`'s listeners from OUTDIR/frames,
///        writes bubbles.json and transfer.report.json.
/// @return the filled tracks, as bubbles.json now holds them
/// @throws io::InputError, io::OutputError; io::Interrupted after a signal (nothing written)
acoustics::BubbleTrackSet transferInFolder(const TransferOptions& options, const sim::Scene& scene,
                                           std::optional<acoustics::BubbleTrackSet> tracks);

int runTransferCommand(const TransferOptions& options);

}  // namespace fluidsound::tools
