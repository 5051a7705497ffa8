// tools/simulate_report.h — what report.json says of a simulation (docs/cli.md): written by
// `simulate` and, as the base of its own report, by `run`.
#pragma once

#include "sim/scene.h"
#include "sim/simulation.h"
#include "tools/run_report.h"
#include "tools/simulate_command.h"

namespace fluidsound::tools {

/// The settings (scene, output, grid, frame rate, CFL, seed) and results (one object per frame
/// made, the bubble count) of `result`; stage times, the command's seconds and an interruption
/// are added by the caller.
void addSimulationResults(RunReport& report, const SimulateOptions& options,
                          const sim::Scene& scene, const sim::SimulationResult& result);

}  // namespace fluidsound::tools
