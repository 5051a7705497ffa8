// tools/command_options.h — the options every subcommand shares, and the physics-model options of
// the commands that render bubbles. Kept free of CLI11 templates (forward declaration only).
#pragma once

#include "acoustics/oscillator_model.h"

namespace CLI {
class App;
}

namespace fluidsound::tools {

/// Options of every subcommand.
struct CommonOptions {
  int threads = 0;     ///< worker threads; 0 = all cores
  bool quiet = false;  ///< no progress, no notes
};

/// Adds --threads and --quiet to a subcommand.
void addCommonOptions(CLI::App& command, CommonOptions& options);

/// Adds the oscillator-model switches (--thermal, --vapour, --hydrostatic, --damping,
/// --excitation, --chirp) to a subcommand; defaults are those of docs/physics.md.
void addOscillatorModelOptions(CLI::App& command, acoustics::OscillatorModel& model);

/// Exit codes of the CLI (docs/cli.md).
enum ExitCode : int {
  kExitSuccess = 0,
  kExitValidationFailed = 1,  ///< `validate` found a row outside its tolerance
  kExitUsage = 2,             ///< bad command line
  kExitBadInput = 3,          ///< an input file is missing or invalid
  kExitOutputFailed = 4,      ///< an output could not be written
  kExitInternal = 5,          ///< anything else (a bug)
  kExitSimulationFailed = 6,  ///< the liquid solver blew up (a velocity not finite)
};

}  // namespace fluidsound::tools
