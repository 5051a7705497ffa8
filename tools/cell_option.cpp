// tools/cell_option.cpp — see cell_option.h.
#include "tools/cell_option.h"

#include <utility>

#include <CLI/CLI.hpp>

#include "io/input_error.h"
#include "io/scene_file.h"

namespace fluidsound::tools {

void addCellOption(CLI::App& command, std::optional<double>& cell) {
  command.add_option(
      "--cell", cell,
      "grid cell size in metres, replacing the scene's domain.cell (same rules: it must "
      "divide the domain into 2 to 1024 whole cells per axis)");
}

sim::Scene sceneAtCellSize(sim::Scene scene, const std::optional<double>& cell) {
  if (!cell) return scene;
  try {
    return io::withCellSize(std::move(scene), *cell, "--cell");
  } catch (const io::InputError& e) {
    throw CLI::ValidationError(e.what());  // a bad option value: exit 2, as CLI11's own checks
  }
}

}  // namespace fluidsound::tools
