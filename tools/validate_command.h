// tools/validate_command.h — `fluidsound validate`: renders single bubbles through the real
// synthesizer, measures them and prints measured vs analytic with pass/fail; exit 1 on failure.
#pragma once

#include <string>

#include "acoustics/bubble/oscillator_model.h"
#include "tools/command_options.h"

namespace fluidsound::tools {

struct ValidateOptions {
  CommonOptions common;
  double sampleRate = 48000.0;
  std::string report;  ///< optional report.json path
  acoustics::OscillatorModel model;
};

CLI::App* addValidateCommand(CLI::App& app, ValidateOptions& options);
int runValidateCommand(const ValidateOptions& options);

}  // namespace fluidsound::tools
