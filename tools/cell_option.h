// tools/cell_option.h — the `--cell METRES` option of `simulate` and `run`: the scene's grid cell
// size replaced after parsing, so that one scene file renders coarse by default and fine on demand.
#pragma once

#include <optional>

#include "sim/scene.h"

namespace CLI {
class App;
}

namespace fluidsound::tools {

/// Adds `--cell METRES` to a subcommand; `cell` stays empty unless the option is given.
void addCellOption(CLI::App& command, std::optional<double>& cell);

/// @brief The scene at the `--cell` size (io::withCellSize), or as it is when `cell` is empty.
/// @param cell  the option's value [m], if given
/// @throws CLI::ValidationError (exit 2, docs/cli.md) naming `--cell` for a size that breaks the
///         rules of `domain.cell`: `--cell: expected …, found …`
sim::Scene sceneAtCellSize(sim::Scene scene, const std::optional<double>& cell);

}  // namespace fluidsound::tools
