// acoustics/transfer/air_wave_solve.cpp — see air_wave_solve.h.
#include "acoustics/transfer/air_wave_solve.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>

#include "acoustics/transfer/rigid_surface_air_field.h"

namespace fluidsound::acoustics {

namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

/// The frame's grid with the absorbing layer around it: cells, faces and what is air.
class AirGrid {
 public:
  AirGrid(const WaterGrid& grid, int layer) : grid_(grid), m_(layer) {
    for (int a = 0; a < 3; ++a) n_[a] = grid.cells[a] + 2 * layer;
    extended_.cells = n_;
    air_.resize(cellCount());
    volume_.resize(cellCount());
    for (int k = 0; k < n_[2]; ++k)
      for (int j = 0; j < n_[1]; ++j)
        for (int i = 0; i < n_[0]; ++i) {
          const std::size_t c = cell(i, j, k);
          const std::size_t g = grid.cellIndex(clampCell(0, i), clampCell(1, j), clampCell(2, k));
          air_[c] = grid.phi[g] >= 0.0f;
          volume_[c] = grid.cellOpen.empty() ? 1.0 : grid.cellOpen[g];
        }
    for (int a = 0; a < 3; ++a) {
      std::array<int, 3> f = n_;
      ++f[a];
      open_[a].assign(static_cast<std::size_t>(f[0]) * f[1] * f[2], 0.0);
      for (int k = 0; k < f[2]; ++k)
        for (int j = 0; j < f[1]; ++j)
          for (int i = 0; i < f[0]; ++i) {
            const std::array<int, 3> at{i, j, k};
            if (at[a] == 0 || at[a] == n_[a]) continue;  // the layer's outer wall: never reached
            std::array<int, 3> lo = at;
            --lo[a];
            if (!air_[cell(lo[0], lo[1], lo[2])] || !air_[cell(i, j, k)]) continue;
            open_[a][face(a, i, j, k)] = gridFaceOpen(a, at);
          }
    }
    // A cell with no open face (inside a solid) takes no part. A cell's open volume is at least
    // its largest open face fraction: a sliver of a cell behind an open face would otherwise need
    // a time step shorter than the grid's own.
    for (int k = 0; k < n_[2]; ++k)
      for (int j = 0; j < n_[1]; ++j)
        for (int i = 0; i < n_[0]; ++i) {
          double largest = 0.0;
          for (int a = 0; a < 3; ++a) {
            std::array<int, 3> hi{i, j, k};
            ++hi[a];
            largest = std::max({largest, open_[a][face(a, i, j, k)], open_[a][face(a, hi[0], hi[1], hi[2])]});
          }
          if (largest <= 0.0) air_[cell(i, j, k)] = false;
          double& v = volume_[cell(i, j, k)];
          v = std::max({v, largest, 1e-3});
        }
  }

  // Cells and faces are indexed as a WaterGrid of the extended counts indexes them.
  std::size_t cellCount() const { return extended_.cellCount(); }
  std::size_t cell(int i, int j, int k) const { return extended_.cellIndex(i, j, k); }
  std::size_t face(int a, int i, int j, int k) const { return extended_.faceIndex(a, i, j, k); }
  const std::array<int, 3>& cells() const { return n_; }
  bool air(std::size_t c) const { return air_[c]; }
  double volume(std::size_t c) const { return volume_[c]; }
  double open(int a, std::size_t f) const { return open_[a][f]; }
  /// The open fractions of the faces normal to axis a, indexed as face() does.
  const double* openFractions(int a) const { return open_[a].data(); }
  double cellSize() const { return grid_.cellSize; }
  /// World position of a point given in extended-cell units (cell i spans [i, i+1]).
  Vec3 world(double i, double j, double k) const {
    const double h = grid_.cellSize;
    return {grid_.origin[0] + (i - m_) * h, grid_.origin[1] + (j - m_) * h,
            grid_.origin[2] + (k - m_) * h};
  }
  /// How deep in the absorbing layer a coordinate x along axis a (extended-cell units) lies, 0 … 1.
  double depthInLayer(int a, double x) const {
    return std::clamp(std::max(m_ - x, x - (n_[a] - m_)) / m_, 0.0, 1.0);
  }
  /// The extended cell holding world point x, or −1 outside.
  long cellAt(const Vec3& x) const {
    std::array<int, 3> c{};
    for (int a = 0; a < 3; ++a) {
      c[a] = static_cast<int>(std::floor((x[a] - grid_.origin[a]) / grid_.cellSize)) + m_;
      if (c[a] < 0 || c[a] >= n_[a]) return -1;
    }
    return static_cast<long>(cell(c[0], c[1], c[2]));
  }

 private:
  int clampCell(int a, int i) const { return std::clamp(i - m_, 0, grid_.cells[a] - 1); }
  /// The open fraction the frame's grid gives a face; beyond the grid, the face nearest inside
  /// it. The grid's own boundary faces carry the fluid's domain walls, which are not walls for
  /// the air, so they read the first interior face instead.
  double gridFaceOpen(int a, const std::array<int, 3>& at) const {
    if (grid_.faceOpen[a].empty()) return 1.0;
    std::array<int, 3> g{};
    for (int b = 0; b < 3; ++b)
      g[b] = b == a ? std::clamp(at[b] - m_, 1, std::max(1, grid_.cells[b] - 1))
                    : std::clamp(at[b] - m_, 0, grid_.cells[b] - 1);
    if (grid_.cells[a] == 1) return 1.0;
    return grid_.faceOpen[a][grid_.faceIndex(a, g[0], g[1], g[2])];
  }

  const WaterGrid& grid_;
  int m_;
  std::array<int, 3> n_{};
  WaterGrid extended_;  ///< only its cell counts: the extended grid's indexing
  std::vector<char> air_;
  std::vector<double> volume_;
  std::array<std::vector<double>, 3> open_;
};

/// The listener's monopole: volume velocity q(t) = exp(−((t − t₀)/τ)²) [m³/s].
/// Half-width of the pulse's support in units of τ: beyond it q < e⁻⁶⁴.
constexpr double kPulseSupport = 8.0;

struct GaussianPulse {
  double tau, t0;
  double q(double t) const { const double x = (t - t0) / tau; return std::exp(-x * x); }
  /// q̇(t) from q(t) already computed (the per-face hot path evaluates the exponential once).
  double dq(double t, double qt) const { return -2.0 * (t - t0) / (tau * tau) * qt; }
  /// Q(ω) = ∫ q e^{−iωt} dt = τ√π e^{−(ωτ/2)²} e^{−iωt₀}.
  Complex spectrum(double w) const {
    return tau * std::sqrt(kPi) * std::exp(-std::pow(w * tau / 2.0, 2)) * std::polar(1.0, -w * t0);
  }
};

/// A face whose rigid part (1 − open fraction) borders air: there the scattered normal velocity
/// is minus the incident one, v_inc·e_a = (q(t_r)/(4πR²) + q̇(t_r)/(4πRc))·(x_f − x_L)_a/R.
struct RigidFace {
  int axis;
  double rigid;  ///< 1 − open fraction
  std::size_t lo, hi;  ///< the cells below and above it along `axis`
  /// Per source (the listener, then its images): R [m] and (x_f − x_source)_a / R.
  std::array<double, kMaxKnownSources> distance{}, cosine{};
};

/// The known field's monopoles: the listener and its images in the ground and the walls, each
/// plane mirroring every source before it (exact for planes at right angles: one per axis).
std::vector<Vec3> knownSources(const Vec3& listener, const AirWaveOptions& options) {
  std::vector<RigidPlane> planes = options.walls;
  if (options.groundHeight) planes.push_back({1, *options.groundHeight});
  std::array<bool, 3> used{};
  for (const RigidPlane& plane : planes) {
    if (plane.axis < 0 || plane.axis > 2 || used[plane.axis] || !std::isfinite(plane.position))
      throw std::invalid_argument("airSidePressure: rigid planes must be finite, one per axis");
    used[plane.axis] = true;
  }
  std::vector<Vec3> sources{listener};
  for (const RigidPlane& plane : planes) {
    const std::size_t count = sources.size();
    for (std::size_t s = 0; s < count; ++s) {
      Vec3 image = sources[s];
      image[plane.axis] = 2.0 * plane.position - image[plane.axis];
      sources.push_back(image);
    }
  }
  return sources;
}

/// Every face whose rigid part borders air, with its distances and direction cosines to the
/// known field's monopoles. @throws std::invalid_argument when a monopole is on a rigid face
std::vector<RigidFace> rigidFaces(const AirGrid& g, const std::vector<Vec3>& sources) {
  const std::array<int, 3> n = g.cells();
  const double h = g.cellSize();
  std::vector<RigidFace> rigid;
  for (int a = 0; a < 3; ++a) {
    std::array<int, 3> f = n;
    ++f[a];
    for (int k = 0; k < f[2]; ++k)
      for (int j = 0; j < f[1]; ++j)
        for (int i = 0; i < f[0]; ++i) {
          const std::array<int, 3> at{i, j, k};
          if (at[a] == 0 || at[a] == n[a]) continue;
          std::array<int, 3> lo = at;
          --lo[a];
          const std::size_t face = g.face(a, i, j, k);
          const bool airLo = g.air(g.cell(lo[0], lo[1], lo[2])), airHi = g.air(g.cell(i, j, k));
          if (!(airLo || airHi) || g.open(a, face) >= 1.0) continue;
          std::array<double, 3> centre{i + 0.5, j + 0.5, k + 0.5};
          centre[a] -= 0.5;
          const Vec3 x = g.world(centre[0], centre[1], centre[2]);
          RigidFace rf{a, 1.0 - g.open(a, face), g.cell(lo[0], lo[1], lo[2]), g.cell(i, j, k)};
          for (std::size_t s = 0; s < sources.size(); ++s) {
            const Vec3& y = sources[s];
            const double r = std::hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]);
            if (!(r > 0.5 * h))
              throw std::invalid_argument("airSidePressure: the listener is on a rigid face");
            rf.distance[s] = r, rf.cosine[s] = (x[a] - y[a]) / r;
          }
          rigid.push_back(rf);
        }
  }
  return rigid;
}

/// For each probe, the air cell holding it, else its nearest air face neighbour; −1 for none.
std::vector<long> probeCells(const AirGrid& g, std::span<const Vec3> probes) {
  const std::array<int, 3> n = g.cells();
  const double h = g.cellSize();
  std::vector<long> probeCell;
  for (const Vec3& x : probes) {
    long found = -1;
    const long at = g.cellAt(x);
    if (at >= 0 && g.air(static_cast<std::size_t>(at))) {
      found = at;
    } else if (at >= 0) {
      double best = 2.0 * h;
      const auto i = static_cast<int>(at % n[0]), j = static_cast<int>(at / n[0] % n[1]),
                 k = static_cast<int>(at / (static_cast<long>(n[0]) * n[1]));
      for (int a = 0; a < 3; ++a)
        for (int s = -1; s <= 1; s += 2) {
          std::array<int, 3> nb{i, j, k};
          nb[a] += s;
          if (nb[a] < 0 || nb[a] >= n[a]) continue;
          const std::size_t cc = g.cell(nb[0], nb[1], nb[2]);
          if (!g.air(cc)) continue;
          const Vec3 centre = g.world(nb[0] + 0.5, nb[1] + 0.5, nb[2] + 0.5);
          const double d = std::hypot(centre[0] - x[0], centre[1] - x[1], centre[2] - x[2]);
          if (d < best) best = d, found = static_cast<long>(cc);
        }
    }
    probeCell.push_back(found);
  }
  return probeCell;
}

/// The solve's field values, in single precision: what it gives is stored as complex floats
/// (wave_air_field.h), and rounding over a few thousand steps stays below 10⁻⁵ of the field,
/// while half the bytes per cell make a step about a third faster.
using Field = float;

/// A row of cells inside the grid proper, [from, to): p −= f · the net flux of the open faces
/// (o·v on each cell's upper face minus its lower face, the upper faces u₁, u₂ on along y and z).
/// Raw pointers, so that the row vectorises.
void pressureRowInside(Field* __restrict p, const Field* __restrict f, const Field* __restrict o0,
                       const Field* __restrict v0, const Field* __restrict o1, const Field* __restrict v1,
                       std::size_t u1, const Field* __restrict o2, const Field* __restrict v2, std::size_t u2,
                       int from, int to) {
  for (int i = from; i < to; ++i)
    p[i] -= f[i] * (o0[i + 1] * v0[i + 1] - o0[i] * v0[i] + o1[i + u1] * v1[i + u1] - o1[i] * v1[i] +
                    o2[i + u2] * v2[i + u2] - o2[i] * v2[i]);
}

/// A row of cells in the absorbing layer, [from, to): each axis's part of p takes its own flux
/// and decays by its own factor (dx per cell, dy and dz for the row); p is their sum.
void pressureRowLayer(Field* __restrict p, Field* __restrict px, Field* __restrict py, Field* __restrict pz,
                      const Field* __restrict f, const Field* __restrict dx, Field dy, Field dz,
                      const Field* __restrict o0, const Field* __restrict v0, const Field* __restrict o1,
                      const Field* __restrict v1, std::size_t u1, const Field* __restrict o2,
                      const Field* __restrict v2, std::size_t u2, int from, int to) {
  for (int i = from; i < to; ++i) {
    px[i] = dx[i] * (px[i] - f[i] * (o0[i + 1] * v0[i + 1] - o0[i] * v0[i]));
    py[i] = dy * (py[i] - f[i] * (o1[i + u1] * v1[i + u1] - o1[i] * v1[i]));
    pz[i] = dz * (pz[i] - f[i] * (o2[i + u2] * v2[i + u2] - o2[i] * v2[i]));
    p[i] = px[i] + py[i] + pz[i];
  }
}

/// One run of the solve: the scattered pressure at each probe's cell, every step.
struct Recording {
  double dt = 0.0;
  GaussianPulse pulse{};
  std::vector<Vec3> sources;      ///< the known field's monopoles
  std::vector<Vec3> probeCentre;  ///< the cell centre each probe reads
  std::vector<char> probeFound;   ///< whether it found an air cell
  std::vector<std::vector<double>> scattered;  ///< [probe][step], p at t = (step + 1)Δt

  /// p_known at probe s per unit volume velocity, e^{+iωt}.
  Complex known(std::size_t s, double w, const AirProperties& air) const {
    Complex sum(0.0);
    for (const Vec3& y : sources) sum += freeFieldAirPressure(probeCentre[s], y, w, air);
    return sum;
  }
};

Recording record(const WaterGrid& grid, const Vec3& listener, std::span<const Vec3> probes,
                 const AirProperties& air, const AirWaveOptions& options) {
  if (grid.phi.size() != grid.cellCount() || !(grid.cellSize > 0.0))
    throw std::invalid_argument("airSidePressure: the grid's arrays do not match its cells");
  if (!(options.maxFrequency > 0.0) || !(options.courant > 0.0 && options.courant <= 1.0) ||
      options.absorbingCells < 1 || !(options.ringTime >= 0.0))
    throw std::invalid_argument("airSidePressure: options out of range");
  const AirGrid g(grid, options.absorbingCells);
  const std::array<int, 3> n = g.cells();
  const double h = g.cellSize(), c = air.soundSpeed, rho = air.density;
  const double dt = options.courant * h / (c * std::sqrt(3.0));
  const double tau = 2.0 * std::sqrt(std::log(1000.0)) / (2.0 * kPi * options.maxFrequency);
  const GaussianPulse pulse{tau, 4.0 * tau};

  // The absorbing layer, a split-field perfectly matched layer (Berenger 1994 in its acoustic
  // form): p = p_x + p_y + p_z, each part damped at σ_a only by the flux along its own axis, and
  // v_a at σ_a, so a wave leaves through any side without reflection in the continuum.
  // σ_a = σ_max d², d the depth into the layer along a; the normal-incidence round trip
  // attenuates by e^{−2σ_max m h/(3c)} = 10⁻⁴. Factors e^{−σΔt} per step, per axis and index.
  const double sigmaMax = 3.0 * c * std::log(1e4) / (2.0 * options.absorbingCells * h);
  std::array<std::vector<Field>, 3> cellDecay, faceDecay;
  for (int a = 0; a < 3; ++a) {
    for (int i = 0; i < n[a]; ++i)
      cellDecay[a].push_back(static_cast<Field>(std::exp(-sigmaMax * std::pow(g.depthInLayer(a, i + 0.5), 2) * dt)));
    for (int i = 0; i <= n[a]; ++i)
      faceDecay[a].push_back(static_cast<Field>(std::exp(-sigmaMax * std::pow(g.depthInLayer(a, i), 2) * dt)));
  }

  const std::vector<Vec3> sources = knownSources(listener, options);
  const std::vector<RigidFace> rigid = rigidFaces(g, sources);
  double farthest = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 x = g.world(corner & 1 ? n[0] : 0, corner & 2 ? n[1] : 0, corner & 4 ? n[2] : 0);
    for (const Vec3& y : sources)
      farthest = std::max(farthest, std::hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]));
  }
  const auto steps = static_cast<long>(std::ceil((pulse.t0 + 4.0 * tau + farthest / c + options.ringTime) / dt));

  const std::vector<long> probeCell = probeCells(g, probes);

  std::array<std::vector<Field>, 3> part;  // p_x, p_y, p_z
  for (auto& pa : part) pa.assign(g.cellCount(), 0.0f);
  std::vector<Field> p(g.cellCount(), 0.0f);  // their sum
  std::array<std::vector<Field>, 3> v;
  std::array<std::vector<Field>, 3> open;  // the faces' open fractions
  for (int a = 0; a < 3; ++a) {
    std::array<std::size_t, 3> f{std::size_t(n[0]), std::size_t(n[1]), std::size_t(n[2])};
    ++f[a];
    v[a].assign(f[0] * f[1] * f[2], 0.0f);
    open[a].assign(g.openFractions(a), g.openFractions(a) + v[a].size());
  }
  Recording rec;
  rec.dt = dt;
  rec.pulse = pulse;
  rec.sources = sources;
  rec.scattered.resize(probes.size());
  for (std::size_t s = 0; s < probes.size(); ++s) {
    rec.probeFound.push_back(probeCell[s] >= 0);
    if (probeCell[s] < 0) {
      rec.probeCentre.push_back(probes[s]);
      continue;
    }
    const auto cc = static_cast<std::size_t>(probeCell[s]);
    rec.probeCentre.push_back(g.world(static_cast<double>(cc % n[0]) + 0.5,
                                      static_cast<double>(cc / n[0] % n[1]) + 0.5,
                                      static_cast<double>(cc / (static_cast<std::size_t>(n[0]) * n[1])) + 0.5));
    rec.scattered[s].reserve(static_cast<std::size_t>(steps));
  }

  const std::array<std::size_t, 3> stride{1, std::size_t(n[0]), std::size_t(n[0]) * n[1]};
  // dt ρc²/(h V) per cell, 0 where there is no air.
  std::vector<Field> cellFactor(g.cellCount(), 0.0f);
  for (std::size_t cc = 0; cc < cellFactor.size(); ++cc)
    if (g.air(cc)) cellFactor[cc] = static_cast<Field>(dt * rho * c * c / (h * g.volume(cc)));
  // 1 on a face with an open part, 0 on a closed one.
  std::array<std::vector<Field>, 3> faceMask;
  for (int a = 0; a < 3; ++a) {
    faceMask[a].resize(v[a].size());
    for (std::size_t f = 0; f < faceMask[a].size(); ++f) faceMask[a][f] = g.open(a, f) > 0.0 ? 1.0f : 0.0f;
  }
  // A cell's decay factor along axis a.
  const auto cellDecayOf = [&](int a, std::size_t cell) {
    const std::size_t coordinate = a == 0 ? cell % n[0] : a == 1 ? cell / n[0] % n[1] : cell / stride[2];
    return cellDecay[a][coordinate];
  };
  // The cells along x that no part of the layer damps: [inside[0], inside[1]).
  std::array<int, 2> inside{n[0], n[0]};
  for (int i = 0; i < n[0]; ++i)
    if (cellDecay[0][i] == 1.0) inside[0] = std::min(inside[0], i), inside[1] = i + 1;
  for (long step = 0; step < steps; ++step) {
    // v^{n+1/2} from p^n on the open faces, a row of faces along x at a time (faces and cells
    // are both contiguous in i); the outer faces of the layer are closed and skipped.
    const auto push = static_cast<Field>(dt / (rho * h));
    tbb::parallel_for(tbb::blocked_range<int>(0, n[2]), [&](const tbb::blocked_range<int>& r) {
      for (int k = r.begin(); k < r.end(); ++k)
        for (int a = 0; a < 3; ++a) {
          if (a == 2 && k == 0) continue;
          Field* va = v[a].data();
          for (int j = (a == 1 ? 1 : 0); j < n[1]; ++j) {
            const std::size_t face0 = g.face(a, 0, j, k), cell0 = g.cell(0, j, k);
            // Branch-free, so the row vectorises: a closed face (mask 0) keeps v = 0.
            const Field* __restrict m = faceMask[a].data() + face0;
            Field* __restrict vr = va + face0;
            const Field* __restrict above = p.data() + cell0;
            const Field* __restrict below = above - stride[a];
            if (a == 0) {
              const Field* __restrict decay = faceDecay[0].data();
              for (int i = 1; i < n[0]; ++i) {
                const Field next = decay[i] * (vr[i] - push * (above[i] - below[i]));
                vr[i] = m[i] * next;
              }
            } else {
              const Field decay = a == 1 ? faceDecay[1][j] : faceDecay[2][k];
              for (int i = 0; i < n[0]; ++i) {
                const Field next = decay * (vr[i] - push * (above[i] - below[i]));
                vr[i] = m[i] * next;
              }
            }
          }
        }
    });

    // p^{n+1} from the flux through the open part of each face (the rigid part's below); a row
    // of cells along x at a time. A cell's upper face along x, y, z is 1, n_x, n_x·n_y faces on.
    const std::array<std::size_t, 3> upFace{1, std::size_t(n[0]), std::size_t(n[0]) * n[1]};
    tbb::parallel_for(tbb::blocked_range<int>(0, n[2]), [&](const tbb::blocked_range<int>& r) {
      for (int k = r.begin(); k < r.end(); ++k)
        for (int j = 0; j < n[1]; ++j) {
          const std::size_t cell0 = g.cell(0, j, k);
          const std::array<std::size_t, 3> face0{g.face(0, 0, j, k), g.face(1, 0, j, k), g.face(2, 0, j, k)};
          // Branch-free rows (a cell that is not air has factor 0 and stays at 0). Inside the
          // grid proper no part is damped, so p itself takes the whole flux; the split parts are
          // kept only in the layer, where a cell's parts decay apart.
          const Field* __restrict f = cellFactor.data() + cell0;
          Field* __restrict pr = p.data() + cell0;
          // Each axis's open fractions and velocities from this row's lower faces; a cell's upper
          // face is 1, n_x, n_x·n_y faces on.
          const Field* __restrict o0 = open[0].data() + face0[0];
          const Field* __restrict o1 = open[1].data() + face0[1];
          const Field* __restrict o2 = open[2].data() + face0[2];
          const Field* __restrict v0 = v[0].data() + face0[0];
          const Field* __restrict v1 = v[1].data() + face0[1];
          const Field* __restrict v2 = v[2].data() + face0[2];
          const std::size_t u1 = upFace[1], u2 = upFace[2];
          const int inFrom = cellDecay[1][j] == 1.0 && cellDecay[2][k] == 1.0 ? inside[0] : n[0];
          const int inTo = inFrom < n[0] ? inside[1] : n[0];
          pressureRowInside(pr, f, o0, v0, o1, v1, u1, o2, v2, u2, inFrom, inTo);
          Field* px = part[0].data() + cell0;
          Field* py = part[1].data() + cell0;
          Field* pz = part[2].data() + cell0;
          const Field dy = cellDecay[1][j], dz = cellDecay[2][k];
          const Field* dx = cellDecay[0].data();
          pressureRowLayer(pr, px, py, pz, f, dx, dy, dz, o0, v0, o1, v1, u1, o2, v2, u2, 0, std::min(inFrom, n[0]));
          if (inFrom < n[0]) pressureRowLayer(pr, px, py, pz, f, dx, dy, dz, o0, v0, o1, v1, u1, o2, v2, u2, inTo, n[0]);
        }
    });
    // The rigid part of each face carries −v_inc (the scattered field cancels the known one's
    // normal velocity there): its flux, out of the cell below and into the cell above, while the
    // pulse passes the face. Added after the open faces' flux, as the same update would, in the
    // face's axis part (inside the grid proper the parts are unused and p takes it alone).
    const double t = (step + 0.5) * dt;
    for (const RigidFace& rf : rigid) {
      double normal = 0.0;
      for (std::size_t s = 0; s < sources.size(); ++s) {
        const double r = rf.distance[s], tr = t - r / c;
        // Beyond 8τ from its peak the pulse is below e⁻⁶⁴ ≈ 10⁻²⁸ of it: nothing arrives.
        if (std::abs(tr - pulse.t0) > kPulseSupport * pulse.tau) continue;
        const double q = pulse.q(tr);
        normal += (q / (4.0 * kPi * r * r) + pulse.dq(tr, q) / (4.0 * kPi * r * c)) * rf.cosine[s];
      }
      if (normal == 0.0) continue;
      const double vInc = -rf.rigid * normal;
      const int a = rf.axis;
      for (const auto& [cell, sign] : {std::pair{rf.lo, -1.0}, std::pair{rf.hi, 1.0}}) {
        const auto delta = static_cast<Field>(sign * cellDecayOf(a, cell) * cellFactor[cell] * vInc);
        part[a][cell] += delta;
        p[cell] += delta;
      }
    }
    for (std::size_t s = 0; s < probes.size(); ++s)
      if (probeCell[s] >= 0) rec.scattered[s].push_back(p[static_cast<std::size_t>(probeCell[s])]);
  }
  return rec;
}

}  // namespace

std::vector<std::vector<Complex>> airSidePressure(const WaterGrid& grid, const Vec3& listener,
                                                  std::span<const Vec3> probes,
                                                  std::span<const double> angularFrequencies,
                                                  const AirProperties& air,
                                                  const AirWaveOptions& options) {
  const Recording rec = record(grid, listener, probes, air, options);
  std::vector<std::vector<Complex>> result(probes.size(),
                                           std::vector<Complex>(angularFrequencies.size(), 0.0));
  for (std::size_t s = 0; s < probes.size(); ++s) {
    if (!rec.probeFound[s]) continue;
    for (std::size_t q = 0; q < angularFrequencies.size(); ++q) {
      const double w = angularFrequencies[q];
      const Complex rotation = std::polar(1.0, -w * rec.dt);
      Complex phasor(1.0), sum(0.0);
      for (const double value : rec.scattered[s]) sum += value * (phasor *= rotation);
      result[s][q] = sum * rec.dt / rec.pulse.spectrum(w) + rec.known(s, w, air);
    }
  }
  return result;
}


AirSideSpectra airSideSpectra(const WaterGrid& grid, const Vec3& listener,
                              std::span<const Vec3> probes, const AirProperties& air,
                              const AirWaveOptions& options) {
  const Recording rec = record(grid, listener, probes, air, options);
  std::size_t length = 1;
  for (const auto& series : rec.scattered) length = std::max(length, series.size());
  std::size_t padded = 1;
  while (padded < 2 * length) padded *= 2;
  AirSideSpectra out;
  out.binSpacing = 1.0 / (static_cast<double>(padded) * rec.dt);
  const auto bins = static_cast<std::size_t>(std::floor(options.maxFrequency / out.binSpacing)) + 1;
  out.pressure.resize(probes.size());
  Eigen::FFT<double> fft;
  std::vector<double> input(padded);
  std::vector<Complex> spectrum;
  for (std::size_t s = 0; s < probes.size(); ++s) {
    if (!rec.probeFound[s]) continue;
    std::fill(input.begin(), input.end(), 0.0);
    std::copy(rec.scattered[s].begin(), rec.scattered[s].end(), input.begin());
    fft.fwd(spectrum, input);
    out.pressure[s].resize(bins);
    for (std::size_t q = 0; q < bins; ++q) {
      const double w = 2.0 * kPi * out.binSpacing * static_cast<double>(q);
      // Sample n is at t = (n + 1)Δt: the transform's e^{−iωnΔt} times e^{−iωΔt}.
      const Complex value = q == 0 ? Complex(0.0)
                                   : spectrum[q] * std::polar(rec.dt, -w * rec.dt) / rec.pulse.spectrum(w) +
                                         rec.known(s, w, air);
      out.pressure[s][q] = value;
    }
  }
  return out;
}

}  // namespace fluidsound::acoustics
