// sim/fluid/velocity_range.h — bubble model, entrainment speed test: the range of each grid velocity
// component around blocks of cells, an upper bound on the speed of a particle relative to the
// liquid sampled anywhere near it, so that tests that cannot pass are skipped unread.
#pragma once

#include <vector>

#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"

namespace fluidsound::sim {

/// @brief Per block of 2³ cells, the smallest and largest value of each MAC velocity component
///        over the faces within 2 blocks of it along each axis. A trilinear sample of the
///        velocity at any point q within 2 cells of a position x (interpolateVelocity, indices
///        clamped to the grid) reads only faces within 3 cells of x's cell, so it lies inside the
///        range of x's block: |v − u(q)| ≤ maxDifference(x, v).
class VelocityRange {
 public:
  VelocityRange(const MacVelocity& velocity, const GridGeometry& grid);

  /// An upper bound [m/s] of |v − u(q)| for every q within reachCells() cells of x (v [m/s]).
  double maxDifference(const Vec3& x, const Vec3& v) const;

  /// How far from x [cells] the bounded samples may lie.
  static constexpr double reachCells() { return 2.0; }

 private:
  /// Widens per-block ranges to the blocks within kSpanBlocks along each axis.
  void widen(std::vector<float>& lo, std::vector<float>& hi);

  GridGeometry grid_;
  Index3 blocks_{0, 0, 0};
  std::vector<float> lo_[3], hi_[3];  ///< per component, per block [m/s]
  std::vector<float> scratchLo_, scratchHi_;  ///< work rows of widen
};

}  // namespace fluidsound::sim
