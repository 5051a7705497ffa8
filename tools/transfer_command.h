// tools/transfer_command.h — `fluidsound transfer SCENE.json -o OUTDIR`: fills the `transfer`
// values of OUTDIR/bubbles.json from the artefacts alone (frames/NNNN.vdb, the scene's listeners
// and solids), with the geometric model (acoustics::computeGeometricTransfer,
// acoustics/transfer/geometric_transfer.h) or the image-source model (acoustics::computeTransfer,
// acoustics/transfer/transfer_stage.h); docs/transfer.md. This command only wires files to them.
#pragma once

#include <optional>
#include <string>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/bubble/oscillator_model.h"
#include "sim/scene.h"
#include "tools/command_options.h"
#include "tools/transfer_choice.h"

namespace fluidsound::tools {

struct TransferOptions {
  CommonOptions common;
  std::string scene;
  std::string output;
  acoustics::OscillatorModel model;  ///< gives each bubble's ω (the model synth renders with)
  std::optional<sim::TransferModel> transfer;  ///< --transfer; empty: the scene's transfer.model
};

CLI::App* addTransferCommand(CLI::App& app, TransferOptions& options);

/// @brief The transfer stage in OUTDIR (options.output): fills the transfer values of `tracks`
///        (the simulation's, handed over in memory by `run`; none: read from OUTDIR/bubbles.json
///        and checked against the scene's listeners) for `scene`'s listeners from OUTDIR/frames
///        (and, for the geometric model, the scene's solids), with the model of
///        transferChoice(scene, options.transfer); writes bubbles.json and transfer.report.json.
/// @return the filled tracks, as bubbles.json now holds them
/// @throws io::InputError (a bad frame, sample or listener; a transfer setting out of range,
///         naming the scene file and e.g. `transfer.max_bands`), io::OutputError;
///         acoustics::TransferSolveError naming the frame whose solve failed; io::Interrupted
///         after a signal. Nothing is written when it throws.
acoustics::BubbleTrackSet transferInFolder(const TransferOptions& options, const sim::Scene& scene,
                                           std::optional<acoustics::BubbleTrackSet> tracks);

int runTransferCommand(const TransferOptions& options);

}  // namespace fluidsound::tools
