// sim/fluid/velocity_range.cpp — see velocity_range.h.
#include "sim/fluid/velocity_range.h"

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

/// `lo`, `hi` hold one value per block of a bi × bj × bk array (x fastest); `row` is scratch.
struct BlockArrays {
  int bi, bj, bk;
  std::size_t line(int j, int k) const { return (static_cast<std::size_t>(k) * bj + j) * bi; }
};

/// out = min (max) of in over [i − span, i + span] ∩ [0, n) along rows of n values (x).
void widenAlongRows(std::vector<float>& lo, std::vector<float>& hi, const BlockArrays& a, std::vector<float>& scratchLo,
                    std::vector<float>& scratchHi) {
  scratchLo.resize(a.bi);
  scratchHi.resize(a.bi);
  for (int k = 0; k < a.bk; ++k)
    for (int j = 0; j < a.bj; ++j) {
      float* const l = &lo[a.line(j, k)];
      float* const h = &hi[a.line(j, k)];
      std::copy(l, l + a.bi, scratchLo.begin());
      std::copy(h, h + a.bi, scratchHi.begin());
      for (int i = 0; i < a.bi; ++i) {
        const int first = std::max(i - kSpanBlocks, 0), last = std::min(i + kSpanBlocks, a.bi - 1);
        float wl = scratchLo[first], wh = scratchHi[first];
        for (int o = first + 1; o <= last; ++o) wl = std::min(wl, scratchLo[o]), wh = std::max(wh, scratchHi[o]);
        l[i] = wl, h[i] = wh;
      }
    }
}

/// Rows of blocks to widen across: `rows` rows of `rowLength` blocks, `rowStride` apart, in each of
/// `planes` planes `planeStride` apart.
struct BlockRows {
  std::size_t rowLength = 0, rowStride = 0;
  int rows = 0, planes = 0;
  std::size_t planeStride = 0;
};

/// The same across rows: each row of blocks becomes the element-wise min (max) of the rows within
/// `span` of it along y (stride one row) or z (stride one plane).
void widenAcrossRows(std::vector<float>& lo, std::vector<float>& hi, const BlockRows& layout,
                     std::vector<float>& scratchLo, std::vector<float>& scratchHi) {
  const std::size_t rowLength = layout.rowLength, rowStride = layout.rowStride,
                    planeStride = layout.planeStride;
  const int rows = layout.rows;
  for (int p = 0; p < layout.planes; ++p) {
    float* const l = &lo[p * planeStride];
    float* const h = &hi[p * planeStride];
    // The original rows of this plane, gathered contiguously.
    scratchLo.resize(rowLength * rows);
    scratchHi.resize(rowLength * rows);
    for (int r = 0; r < rows; ++r) {
      std::copy(l + r * rowStride, l + r * rowStride + rowLength, scratchLo.begin() + r * rowLength);
      std::copy(h + r * rowStride, h + r * rowStride + rowLength, scratchHi.begin() + r * rowLength);
    }
    for (int r = 0; r < rows; ++r) {
      const int first = std::max(r - kSpanBlocks, 0), last = std::min(r + kSpanBlocks, rows - 1);
      float* const outLo = l + r * rowStride;
      float* const outHi = h + r * rowStride;
      std::copy(scratchLo.begin() + first * rowLength, scratchLo.begin() + (first + 1) * rowLength, outLo);
      std::copy(scratchHi.begin() + first * rowLength, scratchHi.begin() + (first + 1) * rowLength, outHi);
      for (int o = first + 1; o <= last; ++o) {
        const float* const inLo = scratchLo.data() + o * rowLength;
        const float* const inHi = scratchHi.data() + o * rowLength;
        for (std::size_t x = 0; x < rowLength; ++x) {
          outLo[x] = std::min(outLo[x], inLo[x]);
          outHi[x] = std::max(outHi[x], inHi[x]);
        }
      }
    }
  }
}

}  // namespace

void VelocityRange::widen(std::vector<float>& lo, std::vector<float>& hi) {
  const int bi = blocks_[0], bj = blocks_[1], bk = blocks_[2];
  const std::size_t plane = static_cast<std::size_t>(bi) * bj;
  widenAlongRows(lo, hi, BlockArrays{bi, bj, bk}, scratchLo_, scratchHi_);
  // Along y: rows of bi blocks, one row apart, within each z-plane.
  widenAcrossRows(lo, hi, BlockRows{std::size_t(bi), std::size_t(bi), bj, bk, plane}, scratchLo_,
                  scratchHi_);
  // Along z: "rows" of a whole plane, one plane apart.
  widenAcrossRows(lo, hi, BlockRows{plane, plane, bk, 1, 0}, scratchLo_, scratchHi_);
}

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
    // Row by row: the range of each pair of faces (kBlockCells = 2), then of the faces left over
    // at the row's end, merged into the row of blocks the row belongs to.
    static_assert(kBlockCells == 2, "the row pass pairs faces");
    const float inf = std::numeric_limits<float>::infinity();
    scratchLo_.resize(bi);
    scratchHi_.resize(bi);
    float* const rowLo = scratchLo_.data();
    float* const rowHi = scratchHi_.data();
    const int n = u.ni(), pairs = std::min(bi, n / 2);
    for (int k = 0; k < u.nk(); ++k)
      for (int j = 0; j < u.nj(); ++j) {
        const float* const row = &u(0, j, k);
        for (int b = 0; b < pairs; ++b) {
          rowLo[b] = std::min(row[2 * b], row[2 * b + 1]);
          rowHi[b] = std::max(row[2 * b], row[2 * b + 1]);
        }
        for (int b = pairs; b < bi; ++b) rowLo[b] = inf, rowHi[b] = -inf;
        for (int i = 2 * pairs; i < n; ++i) {
          const int b = std::min(i / kBlockCells, bi - 1);
          rowLo[b] = std::min(rowLo[b], row[i]), rowHi[b] = std::max(rowHi[b], row[i]);
        }
        const std::size_t b0 = blockIndex(0, std::min(j / kBlockCells, bj - 1), std::min(k / kBlockCells, bk - 1));
        float* const blockLo = &lo[b0];
        float* const blockHi = &hi[b0];
        for (int b = 0; b < bi; ++b) {
          blockLo[b] = std::min(blockLo[b], rowLo[b]);
          blockHi[b] = std::max(blockHi[b], rowHi[b]);
        }
      }
    // Widened by kSpanBlocks blocks along each axis in turn (a running min/max over the window
    // [b − span, b + span] clipped to the grid), whole rows of blocks at a time.
    widen(lo, hi);
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
