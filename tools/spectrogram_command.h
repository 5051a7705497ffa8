// tools/spectrogram_command.h — `fluidsound spectrogram IN.wav -o OUT.png`: the picture of any
// audio file.
#pragma once

#include <string>

#include "io/spectrogram_image.h"
#include "tools/command_options.h"

namespace fluidsound::tools {

struct SpectrogramOptions {
  CommonOptions common;
  std::string input, output;
  io::SpectrogramSettings settings;
};

CLI::App* addSpectrogramCommand(CLI::App& app, SpectrogramOptions& options);
int runSpectrogramCommand(const SpectrogramOptions& options);

}  // namespace fluidsound::tools
