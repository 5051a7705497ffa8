// acoustics/transfer/wave_air_field.cpp — see wave_air_field.h.
#include "acoustics/transfer/wave_air_field.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "acoustics/transfer/air_wave_solve.h"

namespace fluidsound::acoustics {

namespace {

double faceOpenAt(const WaterGrid& g, int axis, int i, int j, int k) {
  return g.faceOpen[axis].empty() ? 1.0 : g.faceOpen[axis][g.faceIndex(axis, i, j, k)];
}

}  // namespace

WaterGrid mergedGrid(const WaterGrid& grid, int factor) {
  if (factor < 1 || grid.cells[0] % factor || grid.cells[1] % factor || grid.cells[2] % factor)
    throw std::invalid_argument("mergedGrid: the factor must divide every cell count");
  if (factor == 1) return grid;
  WaterGrid m;
  for (int a = 0; a < 3; ++a) m.cells[a] = grid.cells[a] / factor;
  m.cellSize = grid.cellSize * factor;
  m.origin = grid.origin;
  m.openSides = grid.openSides;
  m.phi.assign(m.cellCount(), 0.0f);
  m.cellOpen.assign(m.cellCount(), 0.0f);
  const double share = 1.0 / (factor * factor * factor);
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        const std::size_t c = m.cellIndex(i / factor, j / factor, k / factor);
        const std::size_t f = grid.cellIndex(i, j, k);
        m.phi[c] += static_cast<float>(share * grid.phi[f]);
        m.cellOpen[c] += static_cast<float>(share * (grid.cellOpen.empty() ? 1.0 : grid.cellOpen[f]));
      }
  for (int a = 0; a < 3; ++a) {
    std::array<int, 3> n = m.cells;
    ++n[a];
    m.faceOpen[a].assign(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0.0f);
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          const std::array<int, 3> at{i, j, k};
          // Fine faces along a from the lower merged centre to the upper one, clamped to the grid.
          const int lo = std::max(0, (at[a] - 1) * factor + factor / 2);
          const int hi = std::min(grid.cells[a], at[a] * factor + factor / 2);
          double sum = 0.0;
          for (int u = 0; u < factor; ++u)
            for (int v = 0; v < factor; ++v) {
              double least = 1.0;
              for (int s = lo; s <= hi; ++s) {
                std::array<int, 3> fine{};
                fine[a] = s;
                fine[b] = at[b] * factor + u;
                fine[c] = at[c] * factor + v;
                least = std::min(least, faceOpenAt(grid, a, fine[0], fine[1], fine[2]));
              }
              sum += least;
            }
          m.faceOpen[a][m.faceIndex(a, i, j, k)] = static_cast<float>(sum / (factor * factor));
        }
  }
  // A merged cell that a wall crosses (a closed fine face between two of its own fine cells)
  // holds air from both sides of the wall in one pressure node, which would let sound through
  // it: it is shut instead, so the wall is at most one merged cell thick but never leaks.
  for (int k = 0; k < m.cells[2]; ++k)
    for (int j = 0; j < m.cells[1]; ++j)
      for (int i = 0; i < m.cells[0]; ++i) {
        bool walled = false;
        for (int a = 0; a < 3 && !walled; ++a)
          for (int w = 0; w < factor && !walled; ++w)
            for (int v = 0; v < factor && !walled; ++v)
              for (int s = 1; s < factor && !walled; ++s) {
                std::array<int, 3> fine{i * factor, j * factor, k * factor};
                fine[a] += s;
                fine[(a + 1) % 3] += w;
                fine[(a + 2) % 3] += v;
                walled = faceOpenAt(grid, a, fine[0], fine[1], fine[2]) < 0.5;
              }
        if (!walled) continue;
        for (int a = 0; a < 3; ++a) {
          std::array<int, 3> up{i, j, k};
          ++up[a];
          m.faceOpen[a][m.faceIndex(a, i, j, k)] = 0.0f;
          m.faceOpen[a][m.faceIndex(a, up[0], up[1], up[2])] = 0.0f;
        }
      }
  return m;
}

std::optional<double> groundPlaneHeight(const WaterGrid& g) {
  std::optional<int> shared;
  // The grid's top face is the fluid's domain wall, not a wall for the air: a top cell is
  // passable by its lower face instead.
  const auto passable = [&](int i, int j, int k) {
    const int face = j + 1 < g.cells[1] ? j + 1 : j;
    return g.phi[g.cellIndex(i, j, k)] >= 0.0f && faceOpenAt(g, 1, i, face, k) > 0.5;
  };
  for (int k = 0; k < g.cells[2]; ++k)
    for (int i = 0; i < g.cells[0]; ++i) {
      if (i != 0 && i != g.cells[0] - 1 && k != 0 && k != g.cells[2] - 1) continue;
      int ground = 0;
      while (ground < g.cells[1] && !passable(i, ground, k)) ++ground;
      for (int j = ground; j < g.cells[1]; ++j)
        if (!passable(i, j, k)) return std::nullopt;  // not open air all the way up
      if (shared && *shared != ground) return std::nullopt;
      shared = ground;
    }
  if (!shared || *shared == 0 || *shared == g.cells[1]) return std::nullopt;
  return g.origin[1] + *shared * g.cellSize;
}

WaveAirField::WaveAirField(const WaterGrid& frame, const Vec3& listener, const AirProperties& air,
                           const WaveAirOptions& options)
    : listener_(listener), air_(air) {
  int factor = 1;
  for (int f = 2; f * frame.cellSize <= options.cellSize * (1.0 + 1e-9); ++f)
    if (frame.cells[0] % f == 0 && frame.cells[1] % f == 0 && frame.cells[2] % f == 0) factor = f;
  grid_ = mergedGrid(frame, factor);
  const double h = grid_.cellSize;
  maxFrequency_ = air.soundSpeed / (6.0 * h);

  // Probes: every air cell with a liquid cell among its 26 neighbours. Where a liquid cell is a
  // face neighbour (the vertical one first), the cell beyond the probe on the other side is solved
  // too, and the value is carried to the surface between them with ∂p/∂n = 0 there:
  // p(z) = p₀ + a z² through the centres at z = h/2 and 3h/2 gives p₀ = (9p₁ − p₂)/8.
  const std::array<int, 3> n = grid_.cells;
  const auto liquid = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < n[0] && j < n[1] && k < n[2] &&
           grid_.phi[grid_.cellIndex(i, j, k)] < 0.0f;
  };
  const auto open = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < n[0] && j < n[1] && k < n[2] &&
           grid_.phi[grid_.cellIndex(i, j, k)] >= 0.0f;
  };
  std::vector<Vec3> solvePoints;         // the probes' cells, then the cells beyond them
  std::vector<std::optional<Vec3>> outer;  // per probe, the centre of the cell beyond it
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        if (!open(i, j, k)) continue;
        bool nearLiquid = false;
        for (int dk = -1; dk <= 1 && !nearLiquid; ++dk)
          for (int dj = -1; dj <= 1 && !nearLiquid; ++dj)
            for (int di = -1; di <= 1 && !nearLiquid; ++di) nearLiquid = liquid(i + di, j + dj, k + dk);
        if (!nearLiquid) continue;
        probeOfCell_[grid_.cellIndex(i, j, k)] = solvePoints.size();
        const Vec3 centre = grid_.cellCentre(i, j, k);
        solvePoints.push_back(centre);
        probePoint_.push_back(centre);
        outer.emplace_back();
        for (const int a : {1, 0, 2})
          for (const int side : {-1, 1}) {
            std::array<int, 3> in{i, j, k}, out{i, j, k};
            in[a] += side, out[a] -= side;
            // Beyond the grid the solve's absorbing layer continues the edge cell, so the outer
            // cell may lie there.
            const int ci = std::clamp(out[0], 0, n[0] - 1), cj = std::clamp(out[1], 0, n[1] - 1),
                      ck = std::clamp(out[2], 0, n[2] - 1);
            if (outer.back() || !liquid(in[0], in[1], in[2]) || !open(ci, cj, ck)) continue;
            Vec3 surface = centre, beyond = centre;
            surface[a] += side * 0.5 * h;
            beyond[a] -= side * h;
            probePoint_.back() = surface;
            outer.back() = beyond;
          }
      }
  const std::size_t probes = probePoint_.size();
  std::vector<long> beyond(probes, -1);  // index in solvePoints of each probe's outer cell
  for (std::size_t s = 0; s < probes; ++s) {
    if (!outer[s]) continue;
    beyond[s] = static_cast<long>(solvePoints.size());
    solvePoints.push_back(*outer[s]);
  }
  AirWaveOptions solve;
  solve.maxFrequency = maxFrequency_;
  solve.ringTime = options.ringTime;
  solve.absorbingCells = options.absorbingCells;
  solve.groundHeight = groundPlaneHeight(grid_);
  const AirSideSpectra spectra = airSideSpectra(grid_, listener, solvePoints, air, solve);
  binSpacing_ = spectra.binSpacing;
  // A probe the solve found no air cell for (a cell shut in by solids) is not read.
  std::erase_if(probeOfCell_, [&](const auto& entry) { return spectra.pressure[entry.second].size() < 2; });
  spectrum_.resize(probes);
  for (std::size_t s = 0; s < probes; ++s) {
    const auto& p1 = spectra.pressure[s];
    const bool extrapolate = beyond[s] >= 0 && spectra.pressure[static_cast<std::size_t>(beyond[s])].size() == p1.size();
    if (!extrapolate) probePoint_[s] = solvePoints[s];
    const Vec3& x = probePoint_[s];
    const double r = std::hypot(x[0] - listener[0], x[1] - listener[1], x[2] - listener[2]);
    spectrum_[s].resize(p1.size());
    for (std::size_t q = 0; q < p1.size(); ++q) {
      const std::complex<double> value =
          extrapolate ? (9.0 * p1[q] - spectra.pressure[static_cast<std::size_t>(beyond[s])][q]) / 8.0 : p1[q];
      const double k = 2.0 * std::numbers::pi * binSpacing_ * static_cast<double>(q) / air.soundSpeed;
      spectrum_[s][q] = std::complex<float>(value * std::polar(1.0, k * r));
    }
  }
}

std::optional<std::complex<double>> WaveAirField::at(const Vec3& x, double angularFrequency) const {
  const double hz = angularFrequency / (2.0 * std::numbers::pi);
  if (!(hz >= binSpacing_ && hz <= maxFrequency_)) return std::nullopt;
  const double h = grid_.cellSize;
  std::array<int, 3> c{};
  for (int a = 0; a < 3; ++a) c[a] = static_cast<int>(std::floor((x[a] - grid_.origin[a]) / h));
  std::optional<std::size_t> probe;
  double best = 2.0 * h;
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int i = c[0] + di, j = c[1] + dj, k = c[2] + dk;
        if (i < 0 || j < 0 || k < 0 || i >= grid_.cells[0] || j >= grid_.cells[1] || k >= grid_.cells[2]) continue;
        const auto found = probeOfCell_.find(grid_.cellIndex(i, j, k));
        if (found == probeOfCell_.end()) continue;
        const Vec3 centre = grid_.cellCentre(i, j, k);
        const double d = std::hypot(centre[0] - x[0], centre[1] - x[1], centre[2] - x[2]);
        if (d < best) best = d, probe = found->second;
      }
  if (!probe) return std::nullopt;
  const auto& s = spectrum_[*probe];
  const double position = hz / binSpacing_;
  const auto q = std::min(static_cast<std::size_t>(position), s.size() - 2);
  const double t = position - static_cast<double>(q);
  const std::complex<double> smooth =
      (1.0 - t) * std::complex<double>(s[q]) + t * std::complex<double>(s[q + 1]);
  // The propagation phase from the listener to x itself, not to the probe's point.
  const double r = std::hypot(x[0] - listener_[0], x[1] - listener_[1], x[2] - listener_[2]);
  return smooth * std::polar(1.0, -angularFrequency / air_.soundSpeed * r);
}

std::vector<AirResonance> WaveAirField::resonances() const {
  if (!(binSpacing_ > 0.0)) return {};
  std::size_t bins = 0;  // a probe the solve found no air cell for has none
  for (const auto& s : spectrum_) bins = std::max(bins, s.size());
  if (bins < 3) return {};
  // The largest gain over the probes per bin, |p_L| ÷ (2ωρ_a/(4πR)) the doubled free field's
  // magnitude: a vessel's probes share its resonances, and the open liquid around it would
  // dilute a mean.
  std::vector<double> gain(bins, 0.0);
  for (std::size_t s = 0; s < spectrum_.size(); ++s) {
    if (spectrum_[s].size() != bins) continue;
    const Vec3& x = probePoint_[s];
    const double r = std::hypot(x[0] - listener_[0], x[1] - listener_[1], x[2] - listener_[2]);
    for (std::size_t q = 1; q < bins; ++q) {
      const double omega = 2.0 * std::numbers::pi * binSpacing_ * static_cast<double>(q);
      gain[q] = std::max(gain[q], std::abs(std::complex<double>(spectrum_[s][q])) * 4.0 *
                                      std::numbers::pi * r / (2.0 * omega * air_.density));
    }
  }
  const auto first = std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(kResonanceLowHz / binSpacing_)));
  const auto last = std::min(bins - 2, static_cast<std::size_t>(std::min(kResonanceHighHz, maxFrequency_) / binSpacing_));
  struct Peak {
    AirResonance resonance;
    double below, above;  // half-power points [bins]
  };
  std::vector<Peak> peaks;
  for (std::size_t peak = first; peak <= last; ++peak) {
    if (gain[peak] < kMinResonanceGain || gain[peak] < gain[peak - 1] || gain[peak] <= gain[peak + 1]) continue;
    // The half-power points, each between the bins where the gain crosses peak/√2.
    const double half = gain[peak] / std::sqrt(2.0);
    std::optional<double> below, above;
    for (std::size_t q = peak; q > 1 && !below; --q)
      if (gain[q - 1] < half) below = (q - 1) + (half - gain[q - 1]) / (gain[q] - gain[q - 1]);
    for (std::size_t q = peak; q + 1 < bins && !above; ++q)
      if (gain[q + 1] < half) above = q + (gain[q] - half) / (gain[q] - gain[q + 1]);
    if (!below || !above) continue;
    // The peak's own frequency from a parabola through it and its neighbours.
    const double a = gain[peak - 1], b = gain[peak], c = gain[peak + 1];
    const double offset = (a - 2.0 * b + c) < 0.0 ? 0.5 * (a - c) / (a - 2.0 * b + c) : 0.0;
    AirResonance found;
    found.frequency = (static_cast<double>(peak) + offset) * binSpacing_;
    found.decayRate = std::numbers::pi * (*above - *below) * binSpacing_;  // half-width in rad/s
    found.gain = gain[peak];
    peaks.push_back({found, *below, *above});
  }
  std::stable_sort(peaks.begin(), peaks.end(),
                   [](const Peak& x, const Peak& y) { return x.resonance.gain > y.resonance.gain; });
  std::vector<AirResonance> taken;
  std::vector<const Peak*> kept;
  for (const Peak& p : peaks) {
    if (kept.size() == kMaxResonances) break;
    const bool overlaps = std::any_of(kept.begin(), kept.end(), [&](const Peak* k) {
      return p.below < k->above && p.above > k->below;
    });
    if (overlaps) continue;
    kept.push_back(&p);
    taken.push_back(p.resonance);
  }
  return taken;
}

std::size_t WaveAirField::bytes() const {
  std::size_t total = sizeof(*this) + grid_.phi.size() * sizeof(float) + grid_.cellOpen.size() * sizeof(float) +
                      probePoint_.size() * sizeof(Vec3) + probeOfCell_.size() * 2 * sizeof(std::size_t);
  for (const auto& faces : grid_.faceOpen) total += faces.size() * sizeof(float);
  for (const auto& bins : spectrum_) total += bins.size() * sizeof(std::complex<float>);
  return total;
}

}  // namespace fluidsound::acoustics
