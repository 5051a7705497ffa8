// tools/solver_memory.h — refuses, before anything is written, a scene whose grid cannot fit in
// this machine's memory (a `--cell` typo of one digit makes a grid 1000 times larger).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "sim/scene.h"

namespace fluidsound::tools {

/// Bytes per grid cell the liquid solver allocates whatever the liquid [B]: face velocities,
/// weights and openings, solid velocities, the level sets, pressure, multigrid levels, transfer
/// sums. Measured: the glass pour with almost no liquid yet (frame 1) peaks at 145 MB at 0.33 M
/// cells and 780 MB at 2.6 M cells, 277 B per added cell; 250 keeps it a lower bound. Particles
/// (~150 B each, 8 per liquid cell) come on top.
inline constexpr std::uint64_t kSolverBytesPerCell = 250;

/// This machine's physical memory [B] (sysconf), or 0 where it cannot be read.
std::uint64_t physicalMemoryBytes();

/// @brief Throws when the scene's grid alone needs more than `availableBytes`: an
///        io::InputError naming `sceneFile` and `domain.cell` (exit 3), or, when the cell size came
///        from `--cell`, a CLI::ValidationError naming `--cell` (exit 2). Does nothing when
///        `availableBytes` is 0 (unknown).
void requireMemoryForGrid(const sim::Scene& scene, const std::string& sceneFile, const std::optional<double>& cell,
                          std::uint64_t availableBytes);

}  // namespace fluidsound::tools
