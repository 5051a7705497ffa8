// sim/fluid/liquid_state.cpp — see liquid_state.h.
#include "sim/fluid/liquid_state.h"

#include <sstream>
#include <stdexcept>
#include <string>

namespace fluidsound::sim {

namespace {

std::string sizeText(const Index3& s) {
  std::ostringstream out;
  out << s[0] << "×" << s[1] << "×" << s[2];
  return out.str();
}

[[noreturn]] void mismatch(const std::string& field, const std::string& expected, const std::string& found) {
  throw std::invalid_argument("LiquidState." + field + " must have size " + expected + ", got " + found);
}

}  // namespace

void validateLiquidState(const LiquidState& liquid) {
  const std::size_t n = liquid.particlePositions.size();
  if (liquid.particleVelocities.size() != n)
    mismatch("particleVelocities", std::to_string(n), std::to_string(liquid.particleVelocities.size()));
  if (liquid.particleIds.size() != n)
    mismatch("particleIds", std::to_string(n) + " (one id per particle)", std::to_string(liquid.particleIds.size()));
  const GridGeometry& g = liquid.grid;
  if (!(g.cellSize > 0.0) || g.cells[0] < 1 || g.cells[1] < 1 || g.cells[2] < 1) {
    std::ostringstream message;
    message << "LiquidState.grid must have cellSize > 0 and at least one cell per axis, got cellSize " << g.cellSize
            << " m and " << sizeText(g.cells) << " cells";
    throw std::invalid_argument(message.str());
  }
  if (liquid.liquidDistance.size() != g.cells)
    mismatch("liquidDistance", sizeText(g.cells) + " (cells)", sizeText(liquid.liquidDistance.size()));
  if (liquid.solidNodeDistance.size() != g.nodeCount())
    mismatch("solidNodeDistance", sizeText(g.nodeCount()) + " (nodes)", sizeText(liquid.solidNodeDistance.size()));
  for (int a = 0; a < 3; ++a)
    if (liquid.velocity[a].size() != g.faceCount(a))
      mismatch("velocity[" + std::to_string(a) + "]", sizeText(g.faceCount(a)) + " (faces)",
               sizeText(liquid.velocity[a].size()));
}

}  // namespace fluidsound::sim
