// tools/solver_memory.cpp — see solver_memory.h.
#include "tools/solver_memory.h"

#include <unistd.h>

#include <cstdio>

#include <CLI/CLI.hpp>

#include "io/input_error.h"
#include "io/memory_text.h"
#include "sim/fluid/grid.h"

namespace fluidsound::tools {

std::uint64_t physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize) : 0;
}

void requireMemoryForGrid(const sim::Scene& scene, const std::string& sceneFile, const std::optional<double>& cell,
                          std::uint64_t availableBytes) {
  if (availableBytes == 0) return;
  const sim::GridGeometry grid = scene.grid();
  const std::uint64_t cells = static_cast<std::uint64_t>(grid.cells[0]) * grid.cells[1] * grid.cells[2];
  const double needed = static_cast<double>(cells) * kSolverBytesPerCell;
  if (needed <= static_cast<double>(availableBytes)) return;
  char found[160];
  std::snprintf(found, sizeof found,
                "%g m: %d x %d x %d = %.3g cells, at least %s for the solver's grid",
                scene.domain.cell, grid.cells[0], grid.cells[1], grid.cells[2],
                static_cast<double>(cells), io::gibibytes(needed).c_str());
  const std::string expected = "a cell size whose grid fits in this machine's " +
                               io::gibibytes(static_cast<double>(availableBytes)) + " of memory";
  if (cell) throw CLI::ValidationError("--cell: expected " + expected + ", found " + found);
  throw io::InputError(sceneFile, "domain.cell", expected, found);
}

}  // namespace fluidsound::tools
