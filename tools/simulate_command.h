// tools/simulate_command.h — `fluidsound simulate SCENE.json -o OUTDIR`: the liquid simulation,
// writing frames/NNNN.vdb (and .ply with --ply) and report.json.
#pragma once

#include <optional>
#include <string>

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
int runSimulateCommand(const SimulateOptions& options);

}  // namespace fluidsound::tools
