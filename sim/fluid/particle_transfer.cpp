// sim/fluid/particle_transfer.cpp — APIC / FLIP transfers (see particle_transfer.h).
#include "sim/fluid/particle_transfer.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace fluidsound::sim {
namespace {

/// Slab thickness [cells] of the parallel scatter. A particle touches faces within one cell of
/// its own in z, so slabs at least 3 cells thick that are two apart never write the same face.
constexpr int kSlabCells = 4;

/// Trilinear stencil of component `axis` at grid position g (cell units): base face index and
/// fractions. Face (i, j, k) of component a sits at i along a and at +½ along the other axes.
struct Stencil {
  int base[3];
  double frac[3];
};

Stencil faceStencil(const Vec3& g, int axis) {
  Stencil s;
  for (int a = 0; a < 3; ++a) {
    const double x = g[a] - (a == axis ? 0.0 : 0.5);
    const double f = std::floor(x);
    s.base[a] = static_cast<int>(f);
    s.frac[a] = x - f;
  }
  return s;
}

/// The stencils of all three components at one position, from three floors per kind instead of
/// nine: along its own axis a component's faces are node-aligned (x = g), along the others
/// centre-aligned (x = g − ½).
struct PositionStencils {
  int base[2][3];  ///< [0] node-aligned, [1] centre-aligned
  double frac[2][3];

  explicit PositionStencils(const Vec3& g) {
    for (int a = 0; a < 3; ++a)
      for (int kind = 0; kind < 2; ++kind) {
        const double x = g[a] - (kind == 0 ? 0.0 : 0.5);
        const double f = std::floor(x);
        base[kind][a] = static_cast<int>(f);
        frac[kind][a] = x - f;
      }
  }
  /// Same as faceStencil(g, axis).
  Stencil component(int axis) const {
    Stencil s;
    for (int a = 0; a < 3; ++a) {
      const int kind = a == axis ? 0 : 1;
      s.base[a] = base[kind][a];
      s.frac[a] = frac[kind][a];
    }
    return s;
  }
};

/// The values of u at a stencil's 8 corners, di fastest, then dj, then dk; indices clamped to
/// the array (constant extension), as Array3::clamped.
inline void cornerValues(const Array3f& u, const Stencil& st, float out[8]) {
  const Index3& n = u.size();
  if (st.base[0] >= 0 && st.base[1] >= 0 && st.base[2] >= 0 && st.base[0] + 1 < n[0] && st.base[1] + 1 < n[1] &&
      st.base[2] + 1 < n[2]) {
    const float* const f = &u(st.base[0], st.base[1], st.base[2]);
    const std::size_t sj = n[0], sk = static_cast<std::size_t>(n[0]) * n[1];
    for (int dk = 0; dk < 2; ++dk)
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) out[4 * dk + 2 * dj + di] = f[dk * sk + dj * sj + di];
    return;
  }
  for (int dk = 0; dk < 2; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di)
        out[4 * dk + 2 * dj + di] = u.clamped(st.base[0] + di, st.base[1] + dj, st.base[2] + dk);
}

Vec3 toVec3(const Vec3f& v) { return {v[0], v[1], v[2]}; }

int cellOf(const GridGeometry& grid, const Vec3f& p, int axis) {
  return static_cast<int>(std::floor((p[axis] - grid.origin[axis]) / grid.cellSize));
}

}  // namespace

CellIndex sortParticlesByCell(Particles& particles, const GridGeometry& grid) {
  TransferWorkspace workspace;
  return sortParticlesByCell(particles, grid, workspace);
}

const CellIndex& sortParticlesByCell(Particles& particles, const GridGeometry& grid, TransferWorkspace& workspace) {
  const int ni = grid.cells[0], nj = grid.cells[1], nk = grid.cells[2];
  const std::size_t cells = static_cast<std::size_t>(ni) * nj * nk;
  const std::size_t n = particles.size();
  std::vector<std::size_t>& key = workspace.cellOfParticle;
  key.resize(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t p) {
    const int i = cellOf(grid, particles.position[p], 0), j = cellOf(grid, particles.position[p], 1),
              k = cellOf(grid, particles.position[p], 2);
    const bool inside = i >= 0 && j >= 0 && k >= 0 && i < ni && j < nj && k < nk;
    key[p] = inside ? (static_cast<std::size_t>(k) * nj + j) * ni + i : cells;
  });
  // Counting sort (stable): one bucket per cell, one for outside. Counted one slot up, so that
  // after the scatter advanced each bucket's cursor start[c + 1] to its end, start[c] is the
  // start of bucket c again.
  std::vector<std::size_t>& start = workspace.index.start;
  start.assign(cells + 3, 0);
  for (std::size_t p = 0; p < n; ++p) ++start[key[p] + 2];
  for (std::size_t c = 0; c + 1 < start.size(); ++c) start[c + 1] += start[c];
  std::vector<std::size_t>& order = workspace.order;
  order.resize(n);
  for (std::size_t p = 0; p < n; ++p) order[start[key[p] + 1]++] = p;
  start.pop_back();
  Particles& sorted = workspace.sorted;
  sorted.resize(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t q) {
    const std::size_t p = order[q];
    sorted.position[q] = particles.position[p];
    sorted.velocity[q] = particles.velocity[p];
    sorted.affine[q] = particles.affine[p];
    sorted.id[q] = particles.id[p];
  });
  std::swap(particles, sorted);  // the workspace keeps the old arrays for the next sort
  return workspace.index;
}

void particlesToGrid(const Particles& particles, const GridGeometry& grid, TransferScheme scheme,
                     MacVelocity& velocity, std::array<Array3f, 3>& weight) {
  TransferWorkspace workspace;
  particlesToGrid(particles, grid, scheme, velocity, weight, workspace);
}

namespace {
/// The first particle of each z-slab of kSlabCells cells, and the end of the last (the particles
/// are sorted by cell, z slowest; those outside the grid are last and belong to no slab).
std::vector<std::size_t> slabStarts(const Particles& particles, const GridGeometry& grid) {
  const int nk = grid.cells[2];
  const int slabs = (nk + kSlabCells - 1) / kSlabCells;
  std::vector<std::size_t> slabStart(slabs + 1, particles.size());
  const auto insideBelow = [&](const Vec3f& x, int kEnd) {
    const int i = cellOf(grid, x, 0), j = cellOf(grid, x, 1), k = cellOf(grid, x, 2);
    const bool inside = i >= 0 && j >= 0 && k >= 0 && i < grid.cells[0] && j < grid.cells[1] && k < nk;
    return inside && k < kEnd;
  };
  for (int s = 0; s <= slabs; ++s)
    slabStart[s] = static_cast<std::size_t>(
        std::partition_point(particles.position.begin(), particles.position.end(),
                             [&](const Vec3f& x) { return insideBelow(x, s * kSlabCells); }) -
        particles.position.begin());
  return slabStart;
}

/// Adds particle p's trilinear weights and (APIC: affine) momentum to the 8 faces of each
/// velocity component around it.
void scatterParticle(const Particles& particles, std::size_t p, const GridGeometry& grid,
                     TransferScheme scheme, const std::array<FaceSum*, 3>& sums) {
  const double h = grid.cellSize;
  const Vec3 x = toVec3(particles.position[p]);
  const Vec3 g = grid.gridFromWorld(x);
  for (int a = 0; a < 3; ++a) {
    const Stencil st = faceStencil(g, a);
    const Index3 n = grid.faceCount(a);
    // Per axis: the trilinear weight factors and, for APIC, C_p,a,b·(x_face − x_p)_b [m/s].
    double wAxis[3][2], affine[3][2] = {{0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}};
    bool inside = true;
    for (int b = 0; b < 3; ++b) {
      wAxis[b][0] = 1 - st.frac[b];
      wAxis[b][1] = st.frac[b];
      inside = inside && st.base[b] >= 0 && st.base[b] + 1 < n[b];
      if (scheme != TransferScheme::Apic) continue;
      for (int d = 0; d < 2; ++d) {
        const double face = (st.base[b] + d + (a == b ? 0.0 : 0.5)) * h + grid.origin[b] - x[b];
        affine[b][d] = particles.affine[p][a][b] * face;
      }
    }
    const double v = particles.velocity[p][a];
    FaceSum* const sum = sums[a];
    const auto add = [&](std::size_t f, int di, int dj, int dk) {
      const double w = wAxis[0][di] * wAxis[1][dj] * wAxis[2][dk];
      const double vFace =
          scheme == TransferScheme::Apic ? v + (affine[0][di] + affine[1][dj] + affine[2][dk]) : v;
      sum[f].momentum += w * vFace;
      sum[f].weight += w;
    };
    if (inside) {
      const std::size_t base =
          (static_cast<std::size_t>(st.base[2]) * n[1] + st.base[1]) * n[0] + st.base[0];
      const std::size_t sj = n[0], sk = static_cast<std::size_t>(n[0]) * n[1];
      for (int dk = 0; dk < 2; ++dk)
        for (int dj = 0; dj < 2; ++dj)
          for (int di = 0; di < 2; ++di) add(base + dk * sk + dj * sj + di, di, dj, dk);
      continue;
    }
    for (int dk = 0; dk < 2; ++dk)
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
          const int i = st.base[0] + di, j = st.base[1] + dj, k = st.base[2] + dk;
          if (i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2]) continue;
          add((static_cast<std::size_t>(k) * n[1] + j) * n[0] + i, di, dj, dk);
        }
  }
}

/// u = Σ w·v / Σ w and the weight Σ w on every face of component a (0 where no weight), clearing
/// the sums for the next call.
void facesFromSums(FaceSum* const sum, const Index3& faces, Array3f& velocity, Array3f& weight) {
  if (velocity.size() != faces) velocity = Array3f(faces);
  if (weight.size() != faces) weight = Array3f(faces);
  float* const u = velocity.data();
  float* const wsum = weight.data();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, velocity.elementCount()),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t f = r.begin(); f < r.end(); ++f) {
                        const FaceSum fs = sum[f];
                        wsum[f] = static_cast<float>(fs.weight);
                        u[f] = fs.weight > 0.0 ? static_cast<float>(fs.momentum / fs.weight) : 0.0f;
                        sum[f] = FaceSum{};
                      }
                    });
}
}  // namespace

void particlesToGrid(const Particles& particles, const GridGeometry& grid, TransferScheme scheme,
                     MacVelocity& velocity, std::array<Array3f, 3>& weight,
                     TransferWorkspace& workspace) {
  // Momentum and weight sums in double, so the order of ~8 contributions per face hardly matters.
  // The workspace keeps them at zero between calls (the conversion below clears what it reads).
  std::array<FaceSum*, 3> sums;
  for (int a = 0; a < 3; ++a) {
    const Index3 n = grid.faceCount(a);
    const std::size_t count = static_cast<std::size_t>(n[0]) * n[1] * n[2];
    if (workspace.faceSums[a].size() != count) workspace.faceSums[a].assign(count, FaceSum{});
    sums[a] = workspace.faceSums[a].data();
  }
  const std::vector<std::size_t> slabStart = slabStarts(particles, grid);
  const int slabs = static_cast<int>(slabStart.size()) - 1;
  // Even slabs, then odd ones: the faces two slabs share are never written by two tasks at once.
  const auto scatterSlab = [&](int s) {
    for (std::size_t p = slabStart[s]; p < slabStart[s + 1]; ++p)
      scatterParticle(particles, p, grid, scheme, sums);
  };
  for (int phase = 0; phase < 2; ++phase)
    tbb::parallel_for(0, (slabs - phase + 1) / 2, [&](int t) { scatterSlab(2 * t + phase); });
  for (int a = 0; a < 3; ++a) facesFromSums(sums[a], grid.faceCount(a), velocity[a], weight[a]);
}

Vec3 interpolateVelocity(const MacVelocity& velocity, const GridGeometry& grid, const Vec3& p) {
  const PositionStencils stencils(grid.gridFromWorld(p));
  Vec3 out{};
  for (int a = 0; a < 3; ++a) {
    const Stencil st = stencils.component(a);
    float u[8];
    cornerValues(velocity[a], st, u);
    const double wx[2] = {1 - st.frac[0], st.frac[0]}, wy[2] = {1 - st.frac[1], st.frac[1]},
                 wz[2] = {1 - st.frac[2], st.frac[2]};
    double v = 0.0;
    for (int dk = 0; dk < 2; ++dk)
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) v += wx[di] * wy[dj] * wz[dk] * u[4 * dk + 2 * dj + di];
    out[a] = v;
  }
  return out;
}

void gridToParticles(Particles& particles, const MacVelocity& velocity, const MacVelocity& oldVelocity,
                     const GridGeometry& grid, const SolverSettings& settings) {
  const double h = grid.cellSize;
  tbb::parallel_for(std::size_t{0}, particles.size(), [&](std::size_t p) {
    const Vec3 x = toVec3(particles.position[p]);
    if (settings.transfer == TransferScheme::Flip) {
      const Vec3 now = interpolateVelocity(velocity, grid, x);
      const Vec3 before = interpolateVelocity(oldVelocity, grid, x);
      const double r = settings.flipRatio;
      for (int a = 0; a < 3; ++a)
        particles.velocity[p][a] =
            static_cast<float>(r * (particles.velocity[p][a] + now[a] - before[a]) + (1 - r) * now[a]);
      particles.affine[p] = {};
      return;
    }
    const PositionStencils stencils(grid.gridFromWorld(x));
    // ∇w of the trilinear weight [1/m] (Jiang et al. 2015, multilinear APIC): ±1/h per axis.
    const double slope[2] = {-1.0 / h, 1.0 / h};
    for (int a = 0; a < 3; ++a) {
      const Stencil st = stencils.component(a);
      float u[8];
      cornerValues(velocity[a], st, u);
      const double w[3][2] = {{1 - st.frac[0], st.frac[0]}, {1 - st.frac[1], st.frac[1]}, {1 - st.frac[2], st.frac[2]}};
      double v = 0.0, c[3] = {0.0, 0.0, 0.0};
      for (int dk = 0; dk < 2; ++dk)
        for (int dj = 0; dj < 2; ++dj)
          for (int di = 0; di < 2; ++di) {
            const double wx = w[0][di], wy = w[1][dj], wz = w[2][dk], ui = u[4 * dk + 2 * dj + di];
            v += wx * wy * wz * ui;
            c[0] += slope[di] * wy * wz * ui;
            c[1] += slope[dj] * wx * wz * ui;
            c[2] += slope[dk] * wx * wy * ui;
          }
      particles.velocity[p][a] = static_cast<float>(v);
      particles.affine[p][a] = {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
    }
  });
}

}  // namespace fluidsound::sim
