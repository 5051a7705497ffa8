// sim/liquid_distance.cpp — see liquid_distance.h.
#include "sim/liquid_distance.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
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
/// Key width of one bucket of the propagation front [cells²]: a few entries per bucket.
constexpr double kBucketWidthCells2 = 1.0 / 1024.0;
/// Cells per task of the whole-grid passes. Alone (BM_SurfaceDistanceRebuild, the other thread
/// asleep) tasks this small were slower than one task for the glass pour's 41 000 cells (about
/// 385 against 360 µs per rebuild): waking the other thread cost more than it saved. Inside the
/// bubble step the other thread is waiting for the rebuild and takes tasks at once: seven
/// alternating glass pour runs, one task against 8 192-cell tasks (the row phase pass too), gave
/// a bubble model of 0.502 s against 0.486 s on average, 6 of 7 pairs faster.
constexpr std::size_t kCellsPerTask = std::size_t{1} << 13;
/// `limit` of a surface cell: below every squared distance, so no propagated point replaces its
/// own.
constexpr double kNeverReplaced = -1.0;

/// A cell's phase for the sign and the surface: air, liquid, or solid (counted as liquid in the
/// sign, and making no surface).
enum Phase : std::uint8_t { kAir = 0, kLiquid = 1, kSolid = 2 };

}  // namespace

/// The propagation front: (squared distance, cell) entries popped smallest first, ties by cell
/// index. A bucket queue: entries are listed by key in buckets of fixed width; the lowest
/// non-empty bucket (found by a bit per bucket: most are empty) is taken out sorted (the run; a
/// bucket of one entry is popped at once) and popped from its end, and an entry pushed
/// into a bucket at or below the run's is inserted in the run in order. Every entry's key is
/// unique (a cell is pushed again only when strictly closer), so it pops in the same order as any
/// other exact priority queue. Sorting the run, not scanning its bucket for each pop, keeps a
/// crowded bucket cheap: still water under a flat level puts every surface cell's point at the
/// same distance, a bucket of thousands that a scan per pop made quadratic (a still basin's
/// bubble model: 34 s for 2 s of water, now 1 s).
class SurfaceDistance::NearestFirst {
 public:
  struct Entry {
    double key;  ///< [m²]
    Cell cell;
    Vec3 point;  ///< the surface point the key is the squared distance to [m]
    bool operator<(const Entry& o) const {
      return key < o.key || (key == o.key && cell.at < o.cell.at);
    }
  };
  /// Empties the queue for keys of bucket width `width` [m²] up to `largest` [m²] (larger ones
  /// share the last bucket), keeping its memory: a queue popped empty has every bucket empty.
  void reset(double width, double largest) {
    scale_ = 1.0 / width;
    const std::size_t buckets = static_cast<std::size_t>(largest * scale_) + 2;
    if (first_.size() != buckets || size_ != 0) {
      first_.assign(buckets, kNone);
      filled_.assign((buckets + 63) / 64, 0);
    }
    pool_.clear();
    run_.clear();
    cursor_ = 0;
    size_ = 0;
  }
  bool empty() const { return size_ == 0; }
  void push(const Entry& e) {
    ++size_;
    const std::size_t b = std::min(static_cast<std::size_t>(e.key * scale_), first_.size() - 1);
    if (!run_.empty() && b <= runBucket_) {  // among or before the run's entries: in order
      run_.insert(std::lower_bound(run_.begin(), run_.end(), e,
                                   [](const Entry& in, const Entry& x) { return x < in; }),
                  e);
      return;
    }
    pool_.push_back({e, first_[b]});
    first_[b] = static_cast<std::uint32_t>(pool_.size() - 1);
    filled_[b / 64] |= std::uint64_t{1} << (b % 64);
    cursor_ = std::min(cursor_, b);
  }
  Entry pop() {
    --size_;
    if (run_.empty()) {
      // The lowest non-empty bucket, found by its bit; one entry alone is the run, popped at once.
      std::size_t word = cursor_ / 64;
      std::uint64_t bits = filled_[word] & (~std::uint64_t{0} << (cursor_ % 64));
      while (bits == 0) bits = filled_[++word];
      cursor_ = word * 64 + static_cast<std::size_t>(std::countr_zero(bits));
      filled_[word] &= ~(std::uint64_t{1} << (cursor_ % 64));
      const std::uint32_t head = first_[cursor_];
      first_[cursor_] = kNone;
      if (pool_[head].next == kNone) return pool_[head].entry;
      // Otherwise the bucket becomes the run, largest first.
      for (std::uint32_t at = head; at != kNone; at = pool_[at].next)
        run_.push_back(pool_[at].entry);
      runBucket_ = cursor_;
      std::sort(run_.begin(), run_.end(), [](const Entry& a, const Entry& b) { return b < a; });
    }
    const Entry smallest = run_.back();
    run_.pop_back();
    return smallest;
  }

 private:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  struct Node {
    Entry entry;
    std::uint32_t next;
  };
  double scale_ = 1.0;
  std::vector<std::uint32_t> first_;   ///< first node of each bucket
  std::vector<std::uint64_t> filled_;  ///< one bit per bucket: set while it holds entries
  std::vector<Node> pool_;
  std::vector<Entry> run_;  ///< the entries of buckets ≤ runBucket_, largest first
  std::size_t runBucket_ = 0;
  std::size_t cursor_ = 0, size_ = 0;
};

SurfaceDistance::SurfaceDistance() : front_(std::make_unique<NearestFirst>()) {}

SurfaceDistance::SurfaceDistance(const Array3f& phi, const Array3f& solidNodeDistance,
                                 const GridGeometry& grid, double band, double airBand)
    : SurfaceDistance() {
  rebuild(phi, solidNodeDistance, grid, band, airBand);
}

SurfaceDistance::~SurfaceDistance() = default;
SurfaceDistance::SurfaceDistance(SurfaceDistance&&) noexcept = default;
SurfaceDistance& SurfaceDistance::operator=(SurfaceDistance&&) noexcept = default;

void SurfaceDistance::rebuild(const Array3f& phi, const Array3f& solidNodeDistance,
                              const GridGeometry& grid, double band, double airBand) {
  if (airBand == 0.0) airBand = band;
  if (!(band > 0.0)) throw std::invalid_argument("SurfaceDistance: band must be > 0 (metres)");
  if (!(airBand > 0.0 && airBand <= band))
    throw std::invalid_argument("SurfaceDistance: airBand must be in (0, band] (metres)");
  const int ni = grid.cells[0], nj = grid.cells[1], nk = grid.cells[2];
  const std::size_t sj = static_cast<std::size_t>(ni), sk = static_cast<std::size_t>(ni) * nj;
  const std::size_t n = sk * nk;
  // The work array limit_ is padded by one cell on each side.
  const std::size_t psj = static_cast<std::size_t>(ni) + 2, psk = psj * (nj + 2),
                    pn = psk * (nk + 2);
  const auto padded = [&](int i, int j, int k) { return (k + 1) * psk + (j + 1) * psj + (i + 1); };
  if (pn >= std::numeric_limits<std::uint32_t>::max() ||
      std::max({ni, nj, nk}) >= std::numeric_limits<std::int16_t>::max())
    throw std::invalid_argument(
        "SurfaceDistance: more cells than 32-bit indices (16-bit per axis) address");
  const bool newLayout = grid_.cells != grid.cells || limit_.size() != pn;
  grid_ = grid;
  band_ = band;
  airBand_ = airBand;
  const double h = grid.cellSize;
  phase_.resize(n);
  if (newLayout) {
    limit_.assign(pn, kNeverReplaced);  // the padding keeps it: only grid cells are written
  }
  for (int a = 0; a < 3; ++a) {
    centres_[a].resize(grid.cells[a] + 2);
    for (int i = -1; i <= grid.cells[a]; ++i)
      centres_[a][i + 1] = grid.origin[a] + (i + 0.5) * h;  // as cellCentre
  }
  // Whole-grid passes in tasks of at least kCellsPerTask cells: a small grid is one task, run by
  // the calling thread without waking another.
  const int planesPerTask = static_cast<int>(std::max<std::size_t>(1, kCellsPerTask / sk));
  // 0. Phases. A cell is solid when the sum of its 8 nodal solid distances is negative; the solid
  //    cells are found again only when the nodal distances change (static solids: never).
  const std::vector<float>& nodes = solidNodeDistance.values();
  // Compared as bytes (a vectorised memcmp, ~10× faster than comparing floats one by one): equal
  // bytes are equal floats, and bytes that differ between equal floats (±0) only recompute.
  if (nodes.size() != solidNodes_.size() || solidCells_.size() != n ||
      std::memcmp(nodes.data(), solidNodes_.data(), nodes.size() * sizeof(float)) != 0) {
    solidNodes_ = nodes;
    solidCells_.resize(n);
    tbb::parallel_for(tbb::blocked_range<int>(0, nk, planesPerTask),
                      [&](const tbb::blocked_range<int>& r) {
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
                              const float sum = below[i] + below[i + 1] + above[i] + above[i + 1] +
                                                behindBelow[i] + behindBelow[i + 1] +
                                                behindAbove[i] + behindAbove[i + 1];
                              out[i] = sum < 0.0f;
                            }
                          }
                      });
  }
  // Per row of cells (j, k), which phases it holds (bit 1 << phase): rows of one phase whose
  // neighbour rows hold no other phase have no surface cell, and are passed over below.
  // The field starts at ±band (the band of each cell's side), written in the same pass: step 3
  // overwrites the cells the front reaches.
  if (field_.size() != grid.cells) field_ = Array3f(grid.cells);
  const float beyond[2] = {static_cast<float>(airBand), static_cast<float>(-band)};  // by liquid
  rowPhases_.resize(static_cast<std::size_t>(nj) * nk);
  const std::size_t rowsPerTask = std::max<std::size_t>(1, kCellsPerTask / sj);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, rowPhases_.size(), rowsPerTask),
      [&](const tbb::blocked_range<std::size_t>& rows) {
        for (std::size_t row = rows.begin(); row < rows.end(); ++row) {
          const float* const value = phi.data() + row * sj;
          const std::uint8_t* const solid = solidCells_.data() + row * sj;
          std::uint8_t* const out = phase_.data() + row * sj;
          float* const distance = field_.data() + row * sj;
          // Without branches (solid is 0 or 1), so that the loop vectorises.
          std::uint8_t anyAir = 0, anyLiquid = 0, anySolid = 0;
          for (int i = 0; i < ni; ++i) {
            const std::uint8_t inSolid = solid[i];
            const std::uint8_t liquid = static_cast<std::uint8_t>(value[i] < 0.0f) & (inSolid ^ 1u);
            out[i] = static_cast<std::uint8_t>(inSolid * kSolid + liquid * kLiquid);
            distance[i] =
                beyond[inSolid | liquid];  // not air (liquid or solid): the liquid side's band
            anySolid |= inSolid;
            anyLiquid |= liquid;
            anyAir |= (inSolid | liquid) ^ 1u;
          }
          rowPhases_[row] =
              static_cast<std::uint8_t>(anyAir << kAir | anyLiquid << kLiquid | anySolid << kSolid);
        }
      });
  const auto isLiquid = [&](std::size_t at) { return phase_[at] != kAir; };
  // Cells within the band take their first point when it is within their side's band.
  const double band2[2] = {airBand * airBand, band * band};  // by isLiquid
  const double firstLimit[2] = {std::nextafter(band2[0], kUnknown),
                                std::nextafter(band2[1], kUnknown)};
  // 1. Cells next to the surface: the foot of the perpendicular on the plane through the nearest
  //    crossing on each axis (intercepts θ_a·h, directions s_a): normal ∝ (s_a/(θ_a h)), distance
  //    d = 1/√(Σ 1/(θ_a h)²), foot = centre + d²·(s_a/(θ_a h)). Each z-plane lists its own, so the
  //    list is in cell order for any thread count.
  std::vector<std::vector<SurfaceCell>>& surfaceOfPlane = surfaceOfPlane_;
  surfaceOfPlane.resize(nk);
  for (std::vector<SurfaceCell>& plane : surfaceOfPlane) plane.clear();
  solidRow_.assign(ni, kSolid);  // the neighbours of a row at the grid's edge
  tbb::parallel_for(
      tbb::blocked_range<int>(0, nk, planesPerTask), [&](const tbb::blocked_range<int>& r) {
        std::vector<std::uint8_t> crossing(ni);
        for (int k = r.begin(); k < r.end(); ++k)
          for (int j = 0; j < nj; ++j) {
            const std::size_t rowAt = k * sk + j * sj;
            const std::uint8_t* const row = &phase_[rowAt];
            const std::uint8_t* const down = j > 0 ? row - sj : solidRow_.data();
            const std::uint8_t* const up = j + 1 < nj ? row + sj : solidRow_.data();
            const std::uint8_t* const back = k > 0 ? row - sk : solidRow_.data();
            const std::uint8_t* const ahead = k + 1 < nk ? row + sk : solidRow_.data();
            double* const limit = &limit_[padded(0, j, k)];
            const std::size_t rowIndex = static_cast<std::size_t>(k) * nj + j;
            const std::uint8_t held = rowPhases_[rowIndex];
            if (held == 1u << kAir || held == 1u << kLiquid)
              std::fill(limit, limit + ni, firstLimit[held != 1u << kAir]);
            else
              for (int i = 0; i < ni; ++i) limit[i] = firstLimit[row[i] != kAir];
            // A surface cell needs air and liquid in its row or the four rows beside it.
            std::uint8_t nearby = held;
            if (j > 0) nearby |= rowPhases_[rowIndex - 1];
            if (j + 1 < nj) nearby |= rowPhases_[rowIndex + 1];
            if (k > 0) nearby |= rowPhases_[rowIndex - nj];
            if (k + 1 < nk) nearby |= rowPhases_[rowIndex + nj];
            constexpr std::uint8_t kAirAndLiquid = (1u << kAir) | (1u << kLiquid);
            if ((nearby & kAirAndLiquid) != kAirAndLiquid) continue;
            // Most cells are not next to the surface: first a test without branches on the six
            // neighbours (a neighbour outside the grid reads as solid, which makes no crossing; a
            // solid cell makes none either).
            for (int i = 0; i < ni; ++i) {
              const std::uint8_t other = row[i] == kAir ? kLiquid : kAir;
              const std::uint8_t left = i > 0 ? row[i - 1] : std::uint8_t{kSolid};
              const std::uint8_t right = i + 1 < ni ? row[i + 1] : std::uint8_t{kSolid};
              crossing[i] = (row[i] != kSolid) &
                            ((left == other) | (right == other) | (down[i] == other) |
                             (up[i] == other) | (back[i] == other) | (ahead[i] == other));
            }
            for (int i = 0; i < ni; ++i) {
              if (!crossing[i]) continue;
              const std::size_t at = rowAt + i;
              const int index[3] = {i, j, k}, count[3] = {ni, nj, nk};
              const std::size_t stride[3] = {1, sj, sk};
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
              const Vec3 c{centres_[0][i + 1], centres_[1][j + 1], centres_[2][k + 1]};
              const Cell cell{static_cast<std::uint32_t>(padded(i, j, k)),
                              static_cast<std::uint32_t>(at), static_cast<std::int16_t>(i),
                              static_cast<std::int16_t>(j), static_cast<std::int16_t>(k)};
              limit_[cell.at] = kNeverReplaced;
              if (onSurface) {
                surfaceOfPlane[k].push_back({cell, 0.0, c});
                continue;
              }
              const double d2 = 1.0 / (inverse[0] * inverse[0] + inverse[1] * inverse[1] +
                                       inverse[2] * inverse[2]);
              Vec3 foot;
              for (int a = 0; a < 3; ++a) foot[a] = c[a] + d2 * inverse[a];
              surfaceOfPlane[k].push_back({cell, std::sqrt(d2), foot});
            }
          }
      });
  std::vector<SurfaceCell>& surface = surface_;
  surface.clear();
  for (const std::vector<SurfaceCell>& plane : surfaceOfPlane)
    surface.insert(surface.end(), plane.begin(), plane.end());
  // 2. Every other cell within the band: the nearest surface point among those its 26 neighbours
  //    hold, settled in order of distance (Dijkstra's order; closest-point propagation, so the
  //    distance is Euclidean to the point found and no upwind error accumulates with depth).
  //    Ties are broken by cell index: the result is deterministic. limit_ holds, per cell, the
  //    squared distance [m²] a new point must be below to replace its own.
  NearestFirst& front = *front_;
  front.reset(kBucketWidthCells2 * h * h, band * band);
  for (const SurfaceCell& s : surface) front.push({s.distance * s.distance, s.cell, s.point});
  touched_.clear();
  while (!front.empty()) {
    // An entry that is not stale is the cell's latest (keys only decrease), so its point is the
    // cell's closest point.
    const auto [key, cell, p] = front.pop();
    if (limit_[cell.at] != kNeverReplaced && key > limit_[cell.at])
      continue;  // reached closer since
    // Squared distance from p to the 26 neighbours' centres: per axis first, summed in the order
    // x, y, z of the formula (x² + y²) + z², so each is rounded as written out in full. The
    // padding's limit is below every distance: neighbours beyond the grid are never taken.
    const int index[3] = {cell.i, cell.j, cell.k};
    double axis[3][3];
    for (int a = 0; a < 3; ++a)
      for (int d = 0; d < 3; ++d) {
        const double e = centres_[a][index[a] + d] - p[a];  // padded: index + 1 + (d − 1)
        axis[a][d] = e * e;
      }
    // First the 27 distances and which of them beat their cell's limit (one bit each, no branch:
    // a point improves about one neighbour per pop), then the cells they improve. The neighbours
    // are distinct cells, so testing all before updating any gives the same updates.
    double e2[27];
    std::uint32_t improves = 0;
    for (int dz = 0; dz < 3; ++dz)
      for (int dy = 0; dy < 3; ++dy) {
        const double* const limit = &limit_[cell.at + (dz - 1) * static_cast<std::ptrdiff_t>(psk) +
                                            (dy - 1) * static_cast<std::ptrdiff_t>(psj) - 1];
        const double yz = axis[1][dy];
        for (int dx = 0; dx < 3; ++dx) {
          const int n = (dz * 3 + dy) * 3 + dx;
          e2[n] = (axis[0][dx] + yz) + axis[2][dz];
          improves |= static_cast<std::uint32_t>(e2[n] < limit[dx])
                      << n;  // never the cell itself: e2 = limit
        }
      }
    for (; improves != 0; improves &= improves - 1) {
      const int n = std::countr_zero(improves);
      const int dx = n % 3 - 1, dy = n / 3 % 3 - 1, dz = n / 9 - 1;
      const std::ptrdiff_t offset =
          dz * static_cast<std::ptrdiff_t>(psk) + dy * static_cast<std::ptrdiff_t>(psj) + dx;
      const std::ptrdiff_t gridOffset =
          dz * static_cast<std::ptrdiff_t>(sk) + dy * static_cast<std::ptrdiff_t>(sj) + dx;
      const Cell reached{static_cast<std::uint32_t>(cell.at + offset),
                         static_cast<std::uint32_t>(cell.grid + gridOffset),
                         static_cast<std::int16_t>(cell.i + dx),
                         static_cast<std::int16_t>(cell.j + dy),
                         static_cast<std::int16_t>(cell.k + dz)};
      limit_[reached.at] = e2[n];
      touched_.push_back(reached);
      front.push({e2[n], reached, p});
    }
  }
  // 3. The sign of the phase: the cells the front reached (the others hold ±band since the phase
  //    pass, as cells no point reached keep their first limit, beyond their side's band).
  float* const out = field_.data();
  for (const Cell& c : touched_) {
    const std::size_t at = c.grid;
    const double side = isLiquid(at) ? band : airBand;
    const double squared = limit_[c.at];
    const double magnitude = squared <= band2[isLiquid(at)] ? std::sqrt(squared) : side;
    out[at] =
        static_cast<float>(isLiquid(at) ? -std::min(magnitude, side) : std::min(magnitude, side));
  }
  for (const SurfaceCell& s : surface) {  // surface cells: the distance to their own point
    const double magnitude = std::min(s.distance, isLiquid(s.cell.grid) ? band : airBand);
    out[s.cell.grid] = static_cast<float>(isLiquid(s.cell.grid) ? -magnitude : magnitude);
  }
  // 4. The surface points, grouped by bucket (in cell order within a bucket) for at().
  for (int a = 0; a < 3; ++a) buckets_[a] = (grid.cells[a] + kBucketCells - 1) / kBucketCells;
  const auto bucketOf = [&](const Cell& c) {
    return (static_cast<std::size_t>(c.k / kBucketCells) * buckets_[1] + c.j / kBucketCells) *
               buckets_[0] +
           c.i / kBucketCells;
  };
  bucketStart_.assign(static_cast<std::size_t>(buckets_[0]) * buckets_[1] * buckets_[2] + 1, 0);
  for (const SurfaceCell& s : surface) ++bucketStart_[bucketOf(s.cell) + 1];
  for (std::size_t b = 1; b < bucketStart_.size(); ++b) bucketStart_[b] += bucketStart_[b - 1];
  points_.resize(bucketStart_.back());
  std::vector<std::size_t>& next = bucketNext_;
  next.assign(bucketStart_.begin(), bucketStart_.end() - 1);
  for (const SurfaceCell& s : surface) points_[next[bucketOf(s.cell)]++] = s.point;
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
