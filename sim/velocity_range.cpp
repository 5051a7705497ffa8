// sim/velocity_range.cpp — see velocity_range.h.
#include "sim/velocity_range.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fluidsound::sim {

namespace {

/// Cells per block edge: small blocks give tight ranges, and cost more blocks to widen.
constexpr int kBlockCells = 2;
/// A sample within reachCells() = 2 cells of x reads faces within 3 cells of x's cell (2 to the
/// sample, 1 more for its stencil's far corner): the range of a block spans this many blocks on
/// each side.
constexpr int kSpanBlocks = (3 + kBlockCells - 1) / kBlockCells;

}  // namespace

VelocityRange::VelocityRange(const MacVelocity& velocity, const GridGeometry& grid) : grid_(grid) {
  for (int a = 0; a < 3; ++a) blocks_[a] = (grid.cells[a] + kBlockCells - 1) / kBlockCells;
  const int bi = blocks_[0], bj = blocks_[1], bk = blocks_[2];
  const std::size_t count = static_cast<std::size_t>(bi) * bj * bk;
  const auto blockIndex = [&](int i, int j, int k) { return (static_cast<std::size_t>(k) * bj + j) * bi + i; };
  for (int c = 0; c < 3; ++c) {
    // The range over each block's own faces (a face past the last block belongs to the last).
    std::vector<float> lo(count, std::numeric_limits<float>::infinity());
    std::vector<float> hi(count, -std::numeric_limits<float>::infinity());
    const Array3f& u = velocity[c];
    for (int k = 0; k < u.nk(); ++k)
      for (int j = 0; j < u.nj(); ++j) {
        const float* const row = &u(0, j, k);
        const std::size_t b0 = blockIndex(0, std::min(j / kBlockCells, bj - 1), std::min(k / kBlockCells, bk - 1));
        for (int first = 0; first < u.ni(); first += kBlockCells) {
          const std::size_t b = b0 + std::min(first / kBlockCells, bi - 1);
          float rowLo = lo[b], rowHi = hi[b];
          for (int i = first; i < std::min(first + kBlockCells, u.ni()); ++i)
            rowLo = std::min(rowLo, row[i]), rowHi = std::max(rowHi, row[i]);
          lo[b] = rowLo, hi[b] = rowHi;
        }
      }
    // Widened by kSpanBlocks blocks along each axis in turn, one block at a time.
    for (int pass = 0; pass < 3 * kSpanBlocks; ++pass) {
      const int axis = pass / kSpanBlocks;
      std::vector<float> wideLo = lo, wideHi = hi;
      for (int k = 0; k < bk; ++k)
        for (int j = 0; j < bj; ++j)
          for (int i = 0; i < bi; ++i) {
            const int index[3] = {i, j, k};
            const std::size_t b = blockIndex(i, j, k);
            for (const int step : {-1, 1}) {
              if (index[axis] + step < 0 || index[axis] + step >= blocks_[axis]) continue;
              const std::size_t o = axis == 0 ? blockIndex(i + step, j, k)
                                    : axis == 1 ? blockIndex(i, j + step, k)
                                                : blockIndex(i, j, k + step);
              wideLo[b] = std::min(wideLo[b], lo[o]);
              wideHi[b] = std::max(wideHi[b], hi[o]);
            }
          }
      lo.swap(wideLo);
      hi.swap(wideHi);
    }
    lo_[c] = std::move(lo);
    hi_[c] = std::move(hi);
  }
}

double VelocityRange::maxDifference(const Vec3& x, const Vec3& v) const {
  const Vec3 g = grid_.gridFromWorld(x);
  int b[3];
  for (int a = 0; a < 3; ++a) {
    const int cell = std::clamp(static_cast<int>(std::floor(g[a])), 0, grid_.cells[a] - 1);
    b[a] = cell / kBlockCells;
  }
  const std::size_t block = (static_cast<std::size_t>(b[2]) * blocks_[1] + b[1]) * blocks_[0] + b[0];
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double e = std::max(std::abs(v[c] - lo_[c][block]), std::abs(hi_[c][block] - v[c]));
    sum += e * e;
  }
  return std::sqrt(sum);
}

}  // namespace fluidsound::sim
