// sim/liquid_distance.cpp — see liquid_distance.h.
#include "sim/liquid_distance.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sim/cell_interpolation.h"

namespace fluidsound::sim {

namespace {

constexpr double kUnknown = std::numeric_limits<double>::infinity();
/// Surface points are bucketed in cubes of this many cells for nearest-point queries: a few points
/// per bucket on a surface, and few buckets to scan for a bubble several centimetres deep.
constexpr int kBucketCells = 4;
/// at() trusts the grid field where its magnitude is below band − this many cells: the 8 centres
/// of the interpolant lie within √3 cells of the position, so none of them holds the clamped value.
constexpr double kFieldMarginCells = 2.0;

}  // namespace

SurfaceDistance::SurfaceDistance(const Array3f& phi, const Array3f& solidNodeDistance, const GridGeometry& grid,
                                 double band)
    : grid_(grid), band_(band) {
  if (!(band > 0.0)) throw std::invalid_argument("SurfaceDistance: band must be > 0 (metres)");
  const int ni = grid.cells[0], nj = grid.cells[1], nk = grid.cells[2];
  const double h = grid.cellSize;
  const std::size_t sj = static_cast<std::size_t>(ni), sk = static_cast<std::size_t>(ni) * nj;
  const std::size_t n = sk * nk;
  std::vector<std::uint8_t> solid(n, 0), fixed(n, 0), liquid(n, 0);
  std::vector<double> distance(n, kUnknown);
  std::vector<Vec3> closest(n);  ///< the surface point a cell's distance is measured to [m]
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i) {
        float sum = 0.0f;
        for (int c = 0; c < 8; ++c) sum += solidNodeDistance(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2));
        const std::size_t at = k * sk + j * sj + i;
        solid[at] = sum < 0.0f;
        liquid[at] = solid[at] || phi(i, j, k) < 0.0f;
      }
  // 1. Cells next to the surface: the foot of the perpendicular on the plane through the nearest
  //    crossing on each axis (intercepts θ_a·h, directions s_a): normal ∝ (s_a/(θ_a h)), distance
  //    d = 1/√(Σ 1/(θ_a h)²), foot = centre + d²·(s_a/(θ_a h)).
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i) {
        const std::size_t at = k * sk + j * sj + i;
        if (solid[at]) continue;
        const int index[3] = {i, j, k}, count[3] = {ni, nj, nk};
        const std::size_t stride[3] = {1, sj, sk};
        const double here = phi(i, j, k);
        double inverse[3] = {0.0, 0.0, 0.0};  // s_a/(θ_a h) [1/m]
        bool crossing = false, onSurface = false;
        for (int a = 0; a < 3; ++a) {
          double nearest = kUnknown;
          int side = 0;
          for (const int step : {-1, 1}) {
            if (index[a] + step < 0 || index[a] + step >= count[a]) continue;
            const std::size_t other = step < 0 ? at - stride[a] : at + stride[a];
            if (solid[other] || liquid[other] == liquid[at]) continue;
            const double there = phi.data()[other];
            const double along = h * here / (here - there);  // here and there differ in sign
            if (along < nearest) nearest = along, side = step;
          }
          if (nearest == kUnknown) continue;
          crossing = true;
          if (nearest <= 0.0) onSurface = true;
          else inverse[a] = side / nearest;
        }
        if (!crossing) continue;
        const Vec3 centre = grid.cellCentre(i, j, k);
        fixed[at] = 1;
        if (onSurface) {
          distance[at] = 0.0;
          closest[at] = centre;
          continue;
        }
        const double d2 = 1.0 / (inverse[0] * inverse[0] + inverse[1] * inverse[1] + inverse[2] * inverse[2]);
        distance[at] = std::sqrt(d2);
        for (int a = 0; a < 3; ++a) closest[at][a] = centre[a] + d2 * inverse[a];
      }
  // 2. Every other cell: the nearest surface point among those its 26 neighbours hold, settled in
  //    order of distance (Dijkstra's order; closest-point propagation, so the distance is
  //    Euclidean to the point found and no upwind error accumulates with depth). Ties are broken
  //    by cell index: the result is deterministic.
  using Entry = std::pair<double, std::size_t>;  // (squared distance, cell)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> front;
  std::vector<double> squared(n, kUnknown);
  for (std::size_t at = 0; at < n; ++at)
    if (fixed[at]) {
      squared[at] = distance[at] * distance[at];
      front.push({squared[at], at});
    }
  while (!front.empty()) {
    const auto [d2, at] = front.top();
    front.pop();
    if (d2 > squared[at]) continue;  // a stale entry: the cell was reached closer since
    const int i = static_cast<int>(at % sj), j = static_cast<int>((at / sj) % nj), k = static_cast<int>(at / sk);
    const Vec3& p = closest[at];
    for (int dz = -1; dz <= 1; ++dz) {
      if (k + dz < 0 || k + dz >= nk) continue;
      for (int dy = -1; dy <= 1; ++dy) {
        if (j + dy < 0 || j + dy >= nj) continue;
        for (int dx = -1; dx <= 1; ++dx) {
          if (i + dx < 0 || i + dx >= ni || (dx | dy | dz) == 0) continue;
          const std::size_t other = at + dz * static_cast<std::ptrdiff_t>(sk) + dy * static_cast<std::ptrdiff_t>(sj) + dx;
          if (fixed[other]) continue;
          const Vec3 c = grid.cellCentre(i + dx, j + dy, k + dz);
          const double e2 = (c[0] - p[0]) * (c[0] - p[0]) + (c[1] - p[1]) * (c[1] - p[1]) + (c[2] - p[2]) * (c[2] - p[2]);
          if (e2 < squared[other] && e2 <= band * band) {
            squared[other] = e2;
            closest[other] = p;
            front.push({e2, other});
          }
        }
      }
    }
  }
  for (std::size_t at = 0; at < n; ++at)
    if (!fixed[at] && squared[at] != kUnknown) distance[at] = std::sqrt(squared[at]);
  // 3. The sign of the phase; cells beyond the band hold ±band.
  field_ = Array3f(grid.cells);
  float* const out = field_.data();
  for (std::size_t at = 0; at < n; ++at) {
    const double magnitude = std::min(distance[at], band);
    out[at] = static_cast<float>(liquid[at] ? -magnitude : magnitude);
  }
  // 4. The surface points, grouped by bucket (in cell order within a bucket) for at().
  for (int a = 0; a < 3; ++a) buckets_[a] = (grid.cells[a] + kBucketCells - 1) / kBucketCells;
  const auto bucketOf = [&](std::size_t at) {
    const int i = static_cast<int>(at % sj), j = static_cast<int>((at / sj) % nj), k = static_cast<int>(at / sk);
    return (static_cast<std::size_t>(k / kBucketCells) * buckets_[1] + j / kBucketCells) * buckets_[0] + i / kBucketCells;
  };
  bucketStart_.assign(static_cast<std::size_t>(buckets_[0]) * buckets_[1] * buckets_[2] + 1, 0);
  for (std::size_t at = 0; at < n; ++at)
    if (fixed[at]) ++bucketStart_[bucketOf(at) + 1];
  for (std::size_t b = 1; b < bucketStart_.size(); ++b) bucketStart_[b] += bucketStart_[b - 1];
  points_.resize(bucketStart_.back());
  std::vector<std::size_t> next(bucketStart_.begin(), bucketStart_.end() - 1);
  for (std::size_t at = 0; at < n; ++at)
    if (fixed[at]) points_[next[bucketOf(at)]++] = closest[at];
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
          if (std::max({std::abs(bx - home[0]), std::abs(by - home[1]), std::abs(bz - home[2])}) != r) continue;
          const std::size_t b = (static_cast<std::size_t>(bz) * buckets_[1] + by) * buckets_[0] + bx;
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
  if (std::abs(value) < band_ - kFieldMarginCells * grid_.cellSize) return value;
  const double h = grid_.cellSize;
  const double far = h * std::sqrt(static_cast<double>(grid_.cells[0]) * grid_.cells[0] +
                                   static_cast<double>(grid_.cells[1]) * grid_.cells[1] +
                                   static_cast<double>(grid_.cells[2]) * grid_.cells[2]);
  const double magnitude = points_.empty() ? far : nearestSurfacePoint(position);
  return value < 0.0 ? -magnitude : magnitude;
}

}  // namespace fluidsound::sim
