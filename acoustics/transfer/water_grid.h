// acoustics/transfer/water_grid.h — the water side of one frame as the geometric transfer sees it:
// the liquid level set at the solver grid's cell centres, the open fraction of every MAC face
// (the projection's variational solid weights, Batty et al. 2007) and which sides of the grid
// open onto air. A plain value: tools/frame_water_grids.h fills it from a frame's level set and
// the scene's solids at the frame's time; tests fill it by hand. docs/transfer.md.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "sim/core/vec3.h"

namespace fluidsound::acoustics {

/// One frame's liquid and solids on a box of cubic cells. Cell (i, j, k) spans world
/// [origin + (i, j, k)·h, origin + (i+1, j+1, k+1)·h]; arrays are indexed i + n_i·(j + n_j·k).
struct WaterGrid {
  std::array<int, 3> cells{0, 0, 0};  ///< cell counts (n_i, n_j, n_k), each ≥ 1
  double cellSize = 0.0;              ///< h [m], > 0
  Vec3 origin{};                      ///< world position of the grid's minimum corner [m]
  /// Liquid level set φ at the cell centres [m]: < 0 in the liquid, ≥ 0 in air; size n_i·n_j·n_k.
  std::vector<float> phi;
  /// Open fraction [0, 1] of the MAC faces normal to axis a; face (i, j, k) of axis 0 lies at
  /// x = origin + i·h between cells i−1 and i, so the array has one more entry along a
  /// (size (n_i+1)·n_j·n_k for a = 0, indexed i + (n_i+1)·(j + n_j·k)). Empty: every face open.
  std::array<std::vector<float>, 3> faceOpen;
  /// Open volume fraction [0, 1] of each cell (size n_i·n_j·n_k): the mass of the −k_w² term,
  /// which places a wall inside a cell where it is (a flat floor between two faces). Empty: the
  /// mean of the cell's six face fractions.
  std::vector<float> cellOpen;
  /// Grid sides in the order −x, +x, −y, +y, −z, +z: true when air lies beyond (liquid against
  /// that side meets air there), false when it is a rigid wall.
  std::array<bool, 6> openSides{true, true, true, true, true, true};

  std::size_t cellCount() const {
    return static_cast<std::size_t>(cells[0]) * cells[1] * cells[2];
  }
  std::size_t cellIndex(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(cells[0]) * (j + static_cast<std::size_t>(cells[1]) * k);
  }
  /// Index of face (i, j, k) normal to `axis` in faceOpen[axis].
  std::size_t faceIndex(int axis, int i, int j, int k) const {
    std::array<std::size_t, 3> n{std::size_t(cells[0]), std::size_t(cells[1]), std::size_t(cells[2])};
    ++n[axis];
    return i + n[0] * (j + n[1] * static_cast<std::size_t>(k));
  }
  /// World position [m] of the centre of cell (i, j, k).
  Vec3 cellCentre(int i, int j, int k) const {
    return {origin[0] + (i + 0.5) * cellSize, origin[1] + (j + 0.5) * cellSize,
            origin[2] + (k + 0.5) * cellSize};
  }
};

/// The frames of a simulation as water grids. open() is called once per frame that has samples,
/// from several threads at once; it may throw (a missing or damaged frame).
class FrameWaterGrids {
 public:
  virtual ~FrameWaterGrids() = default;
  virtual WaterGrid open(int frame) const = 0;
};

}  // namespace fluidsound::acoustics
