// sim/bubbles/liquid_distance.cpp — see liquid_distance.h.
#include "sim/bubbles/liquid_distance.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "sim/fluid/cell_interpolation.h"

namespace fluidsound::sim {

namespace {

constexpr double kUnknown = std::numeric_limits<double>::infinity();
/// Surface points are bucketed in cubes of this many cells for nearest-point queries: a few points
/// per bucket on a surface, and few buckets to scan for a bubble several centimetres deep.
constexpr int kBucketCells = 4;
/// at() trusts the grid field where its magnitude is below band − this many cells: the 8 centres
/// of the interpolant lie within √3 cells of the position, so none of them holds the clamped value.
constexpr double kFieldMarginCells = 2.0;
/// Cells per task of the whole-grid passes. Alone (BM_SurfaceDistanceRebuild, the other thread
/// asleep) tasks this small were slower than one task for the glass pour's 41 000 cells (about
/// 385 against 360 µs per rebuild): waking the other thread cost more than it saved. Inside the
/// bubble step the other thread is waiting for the rebuild and takes tasks at once: seven
/// alternating glass pour runs, one task against 8 192-cell tasks (the row phase pass too), gave
/// a bubble model of 0.502 s against 0.486 s on average, 6 of 7 pairs faster.
constexpr std::size_t kCellsPerTask = std::size_t{1} << 13;
/// z-planes per task of the band's nearest points: each task takes every point within reach of its
/// planes, so small tasks take each point many times. The glass pour's bubble step (32 planes, a
/// point reaching 6 planes either way), timed inside runs: 170-190 us per rebuild in tasks of 1
/// plane, 157-165 of 4, 138-140 of 8, 195-220 of 16, 250-330 in one task.
constexpr int kPlanesPerTask = 8;

/// The largest float ≤ x.
float floatAtMost(double x) {
  const float f = static_cast<float>(x);
  return f <= x ? f : std::nextafter(f, -std::numeric_limits<float>::infinity());
}

/// A cell's phase for the sign and the surface: air, liquid, or solid (counted as liquid in the
/// sign, and making no surface).
enum Phase : std::uint8_t { kAir = 0, kLiquid = 1, kSolid = 2 };

}  // namespace

SurfaceDistance::SurfaceDistance(const Array3f& phi, const Array3f& solidNodeDistance,
                                 const GridGeometry& grid, double band, double airBand) {
  rebuild(phi, solidNodeDistance, grid, band, airBand);
}

void SurfaceDistance::rebuild(const Array3f& phi, const Array3f& solidNodeDistance,
                              const GridGeometry& grid, double band, double airBand) {
  if (airBand == 0.0) airBand = band;
  if (!(band > 0.0)) throw std::invalid_argument("SurfaceDistance: band must be > 0 (metres)");
  if (!(airBand > 0.0 && airBand <= band))
    throw std::invalid_argument("SurfaceDistance: airBand must be in (0, band] (metres)");
  const std::size_t n = static_cast<std::size_t>(grid.cells[0]) * grid.cells[1] * grid.cells[2];
  if (n >= std::numeric_limits<std::uint32_t>::max() ||
      std::max({grid.cells[0], grid.cells[1], grid.cells[2]}) >=
          std::numeric_limits<std::int16_t>::max())
    throw std::invalid_argument(
        "SurfaceDistance: more cells than 32-bit indices (16-bit per axis) address");
  grid_ = grid;
  band_ = band;
  airBand_ = airBand;
  phase_.resize(n);
  for (int a = 0; a < 3; ++a) {
    centres_[a].resize(grid.cells[a]);
    for (int i = 0; i < grid.cells[a]; ++i)
      centres_[a][i] = grid.origin[a] + (i + 0.5) * grid.cellSize;  // as cellCentre
  }
  findSolidCells(solidNodeDistance);
  classifyCells(phi);
  findSurfaceCells(phi);
  fillBand();
  groupPointsByBucket();
}

int SurfaceDistance::planesPerTask() const {
  // Whole-grid passes in tasks of at least kCellsPerTask cells: a small grid is one task, run by
  // the calling thread without waking another.
  const std::size_t sk = static_cast<std::size_t>(grid_.cells[0]) * grid_.cells[1];
  return static_cast<int>(std::max<std::size_t>(1, kCellsPerTask / sk));
}

SurfaceDistance::Reach SurfaceDistance::reachOf(const Vec3& p) const {
  const double h = grid_.cellSize;
  Reach box;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = static_cast<std::int16_t>(
        std::max(0, static_cast<int>(std::floor((p[a] - band_ - centres_[a][0]) / h)) + 1));
    box.hi[a] = static_cast<std::int16_t>(std::min(
        grid_.cells[a] - 1, static_cast<int>(std::floor((p[a] + band_ - centres_[a][0]) / h))));
  }
  return box;
}

void SurfaceDistance::findSolidCells(const Array3f& solidNodeDistance) {
  // A cell is solid when the sum of its 8 nodal solid distances is negative; the solid cells are
  // found again only when the nodal distances change (static solids: never).
  const int ni = grid_.cells[0], nj = grid_.cells[1], nk = grid_.cells[2];
  const std::size_t sj = static_cast<std::size_t>(ni), sk = sj * nj, n = sk * nk;
  const std::vector<float>& nodes = solidNodeDistance.values();
  // Compared as bytes (a vectorised memcmp, ~10× faster than comparing floats one by one): equal
  // bytes are equal floats, and bytes that differ between equal floats (±0) only recompute.
  if (nodes.size() == solidNodes_.size() && solidCells_.size() == n &&
      std::memcmp(nodes.data(), solidNodes_.data(), nodes.size() * sizeof(float)) == 0)
    return;
  solidNodes_ = nodes;
  solidCells_.resize(n);
  tbb::parallel_for(
      tbb::blocked_range<int>(0, nk, planesPerTask()), [&](const tbb::blocked_range<int>& r) {
        for (int k = r.begin(); k < r.end(); ++k)
          for (int j = 0; j < nj; ++j) {
            const float* const below = &solidNodeDistance(0, j, k);
            const float* const above = &solidNodeDistance(0, j + 1, k);
            const float* const behindBelow = &solidNodeDistance(0, j, k + 1);
            const float* const behindAbove = &solidNodeDistance(0, j + 1, k + 1);
            std::uint8_t* const out = &solidCells_[k * sk + j * sj];
            for (int i = 0; i < ni; ++i) {
              // The 8 nodes in the order (x, then y, then z) of the solver's
              // extendIntoSolids rule.
              const float sum = below[i] + below[i + 1] + above[i] + above[i + 1] + behindBelow[i] +
                                behindBelow[i + 1] + behindAbove[i] + behindAbove[i + 1];
              out[i] = sum < 0.0f;
            }
          }
      });
}

void SurfaceDistance::classifyCells(const Array3f& phi) {
  // Per row of cells (j, k), which phases it holds (bit 1 << phase): rows of one phase whose
  // neighbour rows hold no other phase have no surface cell, and are passed over by
  // findSurfaceCells. The field starts at ±band (the band of each cell's side), written in the
  // same pass: fillBand overwrites the rows the surface points reach.
  const int ni = grid_.cells[0];
  const std::size_t sj = static_cast<std::size_t>(ni);
  if (field_.size() != grid_.cells) field_ = Array3f(grid_.cells);
  const float airBeyond = static_cast<float>(airBand_), liquidBeyond = static_cast<float>(-band_);
  rowPhases_.resize(static_cast<std::size_t>(grid_.cells[1]) * grid_.cells[2]);
  const std::size_t rowsPerTask = std::max<std::size_t>(1, kCellsPerTask / sj);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, rowPhases_.size(), rowsPerTask),
      [&](const tbb::blocked_range<std::size_t>& rows) {
        for (std::size_t row = rows.begin(); row < rows.end(); ++row) {
          const float* const value = phi.data() + row * sj;
          const std::uint8_t* const solid = solidCells_.data() + row * sj;
          std::uint8_t* const out = phase_.data() + row * sj;
          float* const distance = field_.data() + row * sj;
          // Without branches (solid is 0 or 1), so that the loop vectorises: its length and the
          // two bands are local copies, which the byte stores cannot alias (read through the
          // closure, they stopped it).
          std::uint8_t anyAir = 0, anyLiquid = 0, anySolid = 0;
          const int cells = ni;
          const float liquidSide = liquidBeyond, airSide = airBeyond;
          for (int i = 0; i < cells; ++i) {
            const std::uint8_t inSolid = solid[i];
            const std::uint8_t liquid = static_cast<std::uint8_t>(value[i] < 0.0f) & (inSolid ^ 1u);
            out[i] = static_cast<std::uint8_t>(inSolid * kSolid + liquid * kLiquid);
            // Not air (liquid or solid): the liquid side's band (a select: a table lookup does
            // not vectorise).
            distance[i] = (inSolid | liquid) ? liquidSide : airSide;
            anySolid |= inSolid;
            anyLiquid |= liquid;
            anyAir |= (inSolid | liquid) ^ 1u;
          }
          rowPhases_[row] =
              static_cast<std::uint8_t>(anyAir << kAir | anyLiquid << kLiquid | anySolid << kSolid);
        }
      });
}

// Cells next to the surface: the foot of the perpendicular on the plane through the nearest
// crossing on each axis (intercepts θ_a·h, directions s_a): normal ∝ (s_a/(θ_a h)), distance
// d = 1/√(Σ 1/(θ_a h)²), foot = centre + d²·(s_a/(θ_a h)).
SurfaceDistance::SurfaceCell SurfaceDistance::surfaceCellAt(const Array3f& phi, int i, int j,
                                                            int k) const {
  const int ni = grid_.cells[0], nj = grid_.cells[1], nk = grid_.cells[2];
  const std::size_t sj = static_cast<std::size_t>(ni), sk = sj * nj;
  const double h = grid_.cellSize;
  const std::size_t at = k * sk + j * sj + i;
  const int index[3] = {i, j, k}, count[3] = {ni, nj, nk};
  const std::size_t stride[3] = {1, sj, sk};
  const auto isLiquid = [&](std::size_t cell) { return phase_[cell] != kAir; };
  // A crossing on an axis: a neighbour of the other phase that is not solid.
  const auto crossesTo = [&](int a, int step) {
    if (index[a] + step < 0 || index[a] + step >= count[a]) return false;
    const std::size_t other = step < 0 ? at - stride[a] : at + stride[a];
    return phase_[other] != kSolid && isLiquid(other) != isLiquid(at);
  };
  const double here = phi.data()[at];
  double inverse[3] = {0.0, 0.0, 0.0};  // s_a/(θ_a h) [1/m]
  bool onSurface = false;
  for (int a = 0; a < 3; ++a) {
    double nearest = kUnknown;
    int side = 0;
    for (const int step : {-1, 1}) {
      if (!crossesTo(a, step)) continue;
      const double there = phi.data()[step < 0 ? at - stride[a] : at + stride[a]];
      const double along = h * here / (here - there);  // here and there differ in sign
      if (along < nearest) nearest = along, side = step;
    }
    if (nearest == kUnknown) continue;
    if (nearest <= 0.0)
      onSurface = true;
    else
      inverse[a] = side / nearest;
  }
  const Vec3 c{centres_[0][i], centres_[1][j], centres_[2][k]};
  const Cell cell{static_cast<std::uint32_t>(at), static_cast<std::int16_t>(i),
                  static_cast<std::int16_t>(j), static_cast<std::int16_t>(k)};
  if (onSurface) return {cell, 0.0, c, reachOf(c)};
  const double d2 =
      1.0 / (inverse[0] * inverse[0] + inverse[1] * inverse[1] + inverse[2] * inverse[2]);
  Vec3 foot;
  for (int a = 0; a < 3; ++a) foot[a] = c[a] + d2 * inverse[a];
  return {cell, std::sqrt(d2), foot, reachOf(foot)};
}

void SurfaceDistance::findSurfaceCellsOfRow(const Array3f& phi, int j, int k, RowScratch& scratch) {
  const int ni = grid_.cells[0], nj = grid_.cells[1], nk = grid_.cells[2];
  const std::size_t sj = static_cast<std::size_t>(ni), sk = sj * nj;
  const std::size_t rowIndex = static_cast<std::size_t>(k) * nj + j;
  // A surface cell needs air and liquid in its row or the four rows beside it.
  std::uint8_t nearby = rowPhases_[rowIndex];
  if (j > 0) nearby |= rowPhases_[rowIndex - 1];
  if (j + 1 < nj) nearby |= rowPhases_[rowIndex + 1];
  if (k > 0) nearby |= rowPhases_[rowIndex - nj];
  if (k + 1 < nk) nearby |= rowPhases_[rowIndex + nj];
  constexpr std::uint8_t kAirAndLiquid = (1u << kAir) | (1u << kLiquid);
  if ((nearby & kAirAndLiquid) != kAirAndLiquid) return;
  const std::uint8_t* const row = &phase_[k * sk + j * sj];
  const std::uint8_t* const down = j > 0 ? row - sj : solidRow_.data();
  const std::uint8_t* const up = j + 1 < nj ? row + sj : solidRow_.data();
  const std::uint8_t* const back = k > 0 ? row - sk : solidRow_.data();
  const std::uint8_t* const ahead = k + 1 < nk ? row + sk : solidRow_.data();
  // Most cells are not next to the surface: first a test without branches on the six neighbours
  // (a neighbour outside the grid reads as solid, which makes no crossing; a solid cell makes
  // none either).
  const int cells = ni;  // a local copy, which the byte stores cannot alias
  std::copy(row, row + cells, scratch.padded.begin() + 1);
  const std::uint8_t* const beside = scratch.padded.data() + 1;  // beside[-1], beside[cells]
  std::uint8_t* const crosses = scratch.crossing.data();
  for (int i = 0; i < cells; ++i) {
    const std::uint8_t other = row[i] == kAir ? kLiquid : kAir;
    crosses[i] = (row[i] != kSolid) &
                 ((beside[i - 1] == other) | (beside[i + 1] == other) | (down[i] == other) |
                  (up[i] == other) | (back[i] == other) | (ahead[i] == other));
  }
  for (int i = 0; i < ni; ++i)
    if (scratch.crossing[i]) surfaceOfPlane_[k].push_back(surfaceCellAt(phi, i, j, k));
}

void SurfaceDistance::findSurfaceCells(const Array3f& phi) {
  // Each z-plane lists its own, so the list is in cell order for any thread count.
  const int ni = grid_.cells[0], nj = grid_.cells[1], nk = grid_.cells[2];
  surfaceOfPlane_.resize(nk);
  for (std::vector<SurfaceCell>& plane : surfaceOfPlane_) plane.clear();
  solidRow_.assign(ni, kSolid);  // the neighbours of a row at the grid's edge
  tbb::parallel_for(tbb::blocked_range<int>(0, nk, planesPerTask()), [&](const tbb::blocked_range<
                                                                         int>& r) {
    // The row with a solid cell either side: the neighbours beyond its ends.
    RowScratch scratch{std::vector<std::uint8_t>(ni), std::vector<std::uint8_t>(ni + 2, kSolid)};
    for (int k = r.begin(); k < r.end(); ++k)
      for (int j = 0; j < nj; ++j) findSurfaceCellsOfRow(phi, j, k, scratch);
  });
  surface_.clear();
  for (const std::vector<SurfaceCell>& plane : surfaceOfPlane_)
    surface_.insert(surface_.end(), plane.begin(), plane.end());
}

void SurfaceDistance::lowerNearestSquares(int kBegin, int kEnd, std::size_t first, std::size_t last,
                                          std::vector<float>& x2) {
  const int ni = grid_.cells[0], nj = grid_.cells[1];
  const std::size_t sj = static_cast<std::size_t>(ni);
  const double reachBand2 = band_ * band_;
  for (std::size_t q = first; q < last; ++q) {
    const SurfaceCell& s = surface_[q];
    const Vec3& p = s.point;
    const int k0 = std::max<int>(s.reach.lo[2], kBegin),
              k1 = std::min<int>(s.reach.hi[2], kEnd - 1);
    const int i0 = s.reach.lo[0], width = s.reach.hi[0] - i0 + 1;
    for (int i = 0; i < width; ++i) {  // x2: the point's (x_i − p_x)² across its box [m²]
      const double ex = centres_[0][i0 + i] - p[0];
      x2[i] = static_cast<float>(ex * ex);
    }
    for (int k = k0; k <= k1; ++k) {
      const double ez = centres_[2][k] - p[2], z2 = ez * ez;
      for (int j = s.reach.lo[1]; j <= s.reach.hi[1]; ++j) {
        const double ey = centres_[1][j] - p[1], y2 = ey * ey;
        if (y2 + z2 >= reachBand2) continue;
        const std::size_t row = static_cast<std::size_t>(k) * nj + j;
        float* const nearest2 = &nearest2_[row * sj];
        if (!rowReached_[row]) {
          std::fill(nearest2, nearest2 + ni, std::numeric_limits<float>::infinity());
          rowReached_[row] = 1;
        }
        // In floats, four cells to a vector register: 1e-7 relative, far below the O(h) of the
        // points' placement.
        const float yz2 = static_cast<float>(y2 + z2);
        float* const inBox = nearest2 + i0;  // the row's cells in the point's box
        for (int i = 0; i < width; ++i) inBox[i] = std::min(inBox[i], x2[i] + yz2);
      }
    }
  }
}

void SurfaceDistance::writeReachedRows(int kBegin, int kEnd) {
  // For the field, in floats (so that the loop vectorises; the same values as in doubles: the
  // float sqrt is the double one rounded, and d² ≤ band² holds for a float d² exactly when it
  // holds against band² rounded down to a float). Local copies, as in classifyCells.
  const int ni = grid_.cells[0], nj = grid_.cells[1];
  const std::size_t sj = static_cast<std::size_t>(ni);
  const int cells = ni;
  const float liquidLimit2 = floatAtMost(band_ * band_),
              airLimit2 = floatAtMost(airBand_ * airBand_);
  const float liquidSide = static_cast<float>(band_), airSide = static_cast<float>(airBand_);
  for (int k = kBegin; k < kEnd; ++k)
    for (int j = 0; j < nj; ++j) {
      const std::size_t row = static_cast<std::size_t>(k) * nj + j;
      if (!rowReached_[row]) continue;
      const float* const nearest2 = &nearest2_[row * sj];
      const std::uint8_t* const phase = &phase_[row * sj];
      float* const out = field_.data() + row * sj;
      for (int i = 0; i < cells; ++i) {
        const bool liquid = phase[i] != kAir;
        const float magnitude = nearest2[i] <= (liquid ? liquidLimit2 : airLimit2)
                                    ? std::sqrt(nearest2[i])
                                    : (liquid ? liquidSide : airSide);
        out[i] = liquid ? -magnitude : magnitude;
      }
    }
}

void SurfaceDistance::fillBand() {
  // Every other cell within the band: the distance to the nearest surface point. Each point lowers
  // the squared distance held by every cell centre within `band` of it (a brute-force search over
  // the rows of its box that cross its ball: about 700 cells per point at the bubble model's
  // 4.75-cell band, in loops that vectorise), so a cell holds the smallest over all points, in any
  // order: the same bits for any thread count. Tasks own z-planes, each taking the points within
  // reach of its planes; a row is cleared when a point first reaches it. Then the sign of the
  // phase, in the rows points reached (the others hold ±band since classifyCells): a cell takes
  // the distance within its side's band, else the band.
  const int ni = grid_.cells[0], nj = grid_.cells[1], nk = grid_.cells[2];
  // A point lies within a cell of its own cell's centre.
  const int reach = static_cast<int>(std::ceil(band_ / grid_.cellSize)) + 1;
  planeStart_.assign(nk + 1, 0);
  for (int k = 0; k < nk; ++k) planeStart_[k + 1] = planeStart_[k] + surfaceOfPlane_[k].size();
  nearest2_.resize(static_cast<std::size_t>(ni) * nj * nk);
  rowReached_.assign(static_cast<std::size_t>(nj) * nk, 0);
  tbb::parallel_for(
      tbb::blocked_range<int>(0, nk, kPlanesPerTask), [&](const tbb::blocked_range<int>& r) {
        std::vector<float> x2(ni);
        lowerNearestSquares(r.begin(), r.end(), planeStart_[std::max(0, r.begin() - reach)],
                            planeStart_[std::min(nk, r.end() + reach)], x2);
        writeReachedRows(r.begin(), r.end());
      });
  float* const out = field_.data();
  for (const SurfaceCell& s : surface_) {  // surface cells: the distance to their own point
    const bool liquid = phase_[s.cell.grid] != kAir;
    const double magnitude = std::min(s.distance, liquid ? band_ : airBand_);
    out[s.cell.grid] = static_cast<float>(liquid ? -magnitude : magnitude);
  }
}

void SurfaceDistance::groupPointsByBucket() {
  // The surface points, grouped by bucket (in cell order within a bucket) for at().
  for (int a = 0; a < 3; ++a) buckets_[a] = (grid_.cells[a] + kBucketCells - 1) / kBucketCells;
  const auto bucketOf = [&](const Cell& c) {
    return (static_cast<std::size_t>(c.k / kBucketCells) * buckets_[1] + c.j / kBucketCells) *
               buckets_[0] +
           c.i / kBucketCells;
  };
  bucketStart_.assign(static_cast<std::size_t>(buckets_[0]) * buckets_[1] * buckets_[2] + 1, 0);
  for (const SurfaceCell& s : surface_) ++bucketStart_[bucketOf(s.cell) + 1];
  for (std::size_t b = 1; b < bucketStart_.size(); ++b) bucketStart_[b] += bucketStart_[b - 1];
  points_.resize(bucketStart_.back());
  bucketNext_.assign(bucketStart_.begin(), bucketStart_.end() - 1);
  for (const SurfaceCell& s : surface_) points_[bucketNext_[bucketOf(s.cell)]++] = s.point;
}

double SurfaceDistance::nearestSurfacePoint(const Vec3& p) const {
  const double bucketSize = kBucketCells * grid_.cellSize;
  const Vec3 g = grid_.gridFromWorld(p);
  int home[3];
  for (int a = 0; a < 3; ++a)
    home[a] = std::clamp(static_cast<int>(std::floor(g[a] / kBucketCells)), 0, buckets_[a] - 1);
  const int rings = std::max({buckets_[0], buckets_[1], buckets_[2]});
  double best2 = kUnknown;
  for (int r = 0; r <= rings; ++r) {
    // Every bucket of ring r is at least (r − 1) buckets from p (p may lie anywhere in its own,
    // or outside the grid, which only makes the buckets further).
    const double reach = std::max(0, r - 1) * bucketSize;
    if (reach * reach >= best2) break;
    for (int bz = home[2] - r; bz <= home[2] + r; ++bz) {
      if (bz < 0 || bz >= buckets_[2]) continue;
      for (int by = home[1] - r; by <= home[1] + r; ++by) {
        if (by < 0 || by >= buckets_[1]) continue;
        for (int bx = home[0] - r; bx <= home[0] + r; ++bx) {
          if (bx < 0 || bx >= buckets_[0]) continue;
          if (std::max({std::abs(bx - home[0]), std::abs(by - home[1]), std::abs(bz - home[2])}) !=
              r)
            continue;
          const std::size_t b =
              (static_cast<std::size_t>(bz) * buckets_[1] + by) * buckets_[0] + bx;
          for (std::size_t q = bucketStart_[b]; q < bucketStart_[b + 1]; ++q) {
            const Vec3& s = points_[q];
            best2 = std::min(best2, (s[0] - p[0]) * (s[0] - p[0]) + (s[1] - p[1]) * (s[1] - p[1]) +
                                        (s[2] - p[2]) * (s[2] - p[2]));
          }
        }
      }
    }
  }
  return std::sqrt(best2);
}

double SurfaceDistance::at(const Vec3& position) const {
  const double value = interpolateCellCentres(field_, grid_, position);
  if (std::abs(value) < (value < 0.0 ? band_ : airBand_) - kFieldMarginCells * grid_.cellSize)
    return value;
  const double h = grid_.cellSize;
  const double far = h * std::sqrt(static_cast<double>(grid_.cells[0]) * grid_.cells[0] +
                                   static_cast<double>(grid_.cells[1]) * grid_.cells[1] +
                                   static_cast<double>(grid_.cells[2]) * grid_.cells[2]);
  const double magnitude = points_.empty() ? far : nearestSurfacePoint(position);
  return value < 0.0 ? -magnitude : magnitude;
}

}  // namespace fluidsound::sim
