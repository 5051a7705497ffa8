// tools/modes_command.h — `fluidsound modes MESH --material NAME`: a body's vibration modes
// (frequency, decay, the count left after compression), to check a model before a render
// (docs/solids.md, docs/cli.md).
#pragma once

#include <optional>
#include <string>

#include "tools/command_options.h"

namespace fluidsound::tools {

struct ModesOptions {
  CommonOptions common;
  std::string mesh;
  std::string material = "steel";
  std::optional<double> density, youngsModulus, poissonsRatio, rayleighMass, rayleighStiffness;
  double scale = 1.0;
  int resolution = 32;  ///< voxels along the body's longest side
  int maxModes = 200;
  double maxFrequency = 20000.0;  ///< [Hz]
  std::string clamp;              ///< a face of the body's box held fixed: -x, +x, -y, +y, -z, +z
  bool json = false;
  std::string cache;  ///< a folder for the modal models (KEY.modes); empty: none
};

CLI::App* addModesCommand(CLI::App& app, ModesOptions& options);
int runModesCommand(const ModesOptions& options);

}  // namespace fluidsound::tools
