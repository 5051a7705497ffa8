// tools/simulate_command.h — `fluidsound simulate SCENE.json -o OUTDIR`: the liquid simulation,
// writing frames/NNNN.vdb (and .ply with --ply), bubbles.json and report.json.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "acoustics/bubble/bubble_track.h"
#include "tools/command_options.h"

namespace fluidsound::tools {

struct SimulateOptions {
  CommonOptions common;
  std::string scene;
  std::string output;
  std::string frames;  ///< "A:B" (inclusive), default all
  bool ply = false;
  std::optional<double> cell;  ///< --cell: grid cell size [m] replacing domain.cell
};

CLI::App* addSimulateCommand(CLI::App& app, SimulateOptions& options);

/// What a simulation left besides its files: the bubble tracks bubbles.json holds (no transfer
/// values yet) and the report.json document, for `run` to carry on in memory.
struct SimulateOutcome {
  acoustics::BubbleTrackSet tracks;
  nlohmann::ordered_json report;
};

/// @brief `simulate`: reads the scene, runs sim::simulate and writes the frames, bubbles.json and
///        report.json into options.output.
/// @throws io::InputError, io::OutputError; io::Interrupted after a signal, once report.json says
///         where the simulation stopped (no bubbles.json then)
SimulateOutcome simulateIntoFolder(const SimulateOptions& options);

int runSimulateCommand(const SimulateOptions& options);

}  // namespace fluidsound::tools
