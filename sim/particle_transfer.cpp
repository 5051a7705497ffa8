// sim/particle_transfer.cpp — APIC / FLIP transfers (see particle_transfer.h).
#include "sim/particle_transfer.h"

#include <algorithm>
#include <cmath>

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

Vec3 toVec3(const Vec3f& v) { return {v[0], v[1], v[2]}; }

int cellOf(const GridGeometry& grid, const Vec3f& p, int axis) {
  return static_cast<int>(std::floor((p[axis] - grid.origin[axis]) / grid.cellSize));
}

}  // namespace

CellIndex sortParticlesByCell(Particles& particles, const GridGeometry& grid) {
  const int ni = grid.cells[0], nj = grid.cells[1], nk = grid.cells[2];
  const std::size_t cells = static_cast<std::size_t>(ni) * nj * nk;
  const std::size_t n = particles.size();
  std::vector<std::size_t> key(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t p) {
    const int i = cellOf(grid, particles.position[p], 0), j = cellOf(grid, particles.position[p], 1),
              k = cellOf(grid, particles.position[p], 2);
    const bool inside = i >= 0 && j >= 0 && k >= 0 && i < ni && j < nj && k < nk;
    key[p] = inside ? (static_cast<std::size_t>(k) * nj + j) * ni + i : cells;
  });
  // Counting sort (stable): one bucket per cell, one for outside.
  std::vector<std::size_t> start(cells + 2, 0);
  for (std::size_t p = 0; p < n; ++p) ++start[key[p] + 1];
  for (std::size_t c = 0; c + 1 < start.size(); ++c) start[c + 1] += start[c];
  const CellIndex index{start};  // before the scatter below advances the bucket starts
  std::vector<std::size_t> order(n);
  for (std::size_t p = 0; p < n; ++p) order[start[key[p]]++] = p;
  Particles sorted;
  sorted.resize(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t q) {
    const std::size_t p = order[q];
    sorted.position[q] = particles.position[p];
    sorted.velocity[q] = particles.velocity[p];
    sorted.affine[q] = particles.affine[p];
  });
  particles = std::move(sorted);
  return index;
}

void particlesToGrid(const Particles& particles, const GridGeometry& grid, TransferScheme scheme,
                     MacVelocity& velocity, std::array<Array3f, 3>& weight) {
  const double h = grid.cellSize;
  const int nk = grid.cells[2];
  // Momentum and weight sums in double, so the order of ~8 contributions per face hardly matters.
  std::array<Array3d, 3> momentum, mass;
  for (int a = 0; a < 3; ++a) {
    momentum[a] = Array3d(grid.faceCount(a), 0.0);
    mass[a] = Array3d(grid.faceCount(a), 0.0);
  }
  // Particle ranges of each slab (particles are sorted by cell, z slowest).
  const int slabs = (nk + kSlabCells - 1) / kSlabCells;
  std::vector<std::size_t> slabStart(slabs + 1, particles.size());
  {
    std::size_t p = 0;
    for (int s = 0; s <= slabs; ++s) {
      while (p < particles.size()) {
        const int k = cellOf(grid, particles.position[p], 2);
        const int i = cellOf(grid, particles.position[p], 0), j = cellOf(grid, particles.position[p], 1);
        const bool inside = i >= 0 && j >= 0 && k >= 0 && i < grid.cells[0] && j < grid.cells[1] && k < nk;
        if (!inside || k >= s * kSlabCells) break;
        ++p;
      }
      slabStart[s] = p;
    }
  }
  const auto scatterSlab = [&](int s) {
    for (std::size_t p = slabStart[s]; p < slabStart[s + 1]; ++p) {
      const Vec3 x = toVec3(particles.position[p]);
      const Vec3 g = grid.gridFromWorld(x);
      for (int a = 0; a < 3; ++a) {
        const Stencil st = faceStencil(g, a);
        const Array3d& m = mass[a];
        for (int dk = 0; dk < 2; ++dk)
          for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di) {
              const int i = st.base[0] + di, j = st.base[1] + dj, k = st.base[2] + dk;
              if (!m.contains(i, j, k)) continue;
              const double w = (di ? st.frac[0] : 1 - st.frac[0]) * (dj ? st.frac[1] : 1 - st.frac[1]) *
                               (dk ? st.frac[2] : 1 - st.frac[2]);
              double v = particles.velocity[p][a];
              if (scheme == TransferScheme::Apic) {
                // Face position minus particle position [m].
                const double face[3] = {(i + (a == 0 ? 0.0 : 0.5)) * h + grid.origin[0] - x[0],
                                        (j + (a == 1 ? 0.0 : 0.5)) * h + grid.origin[1] - x[1],
                                        (k + (a == 2 ? 0.0 : 0.5)) * h + grid.origin[2] - x[2]};
                const Vec3f& c = particles.affine[p][a];
                v += c[0] * face[0] + c[1] * face[1] + c[2] * face[2];
              }
              momentum[a](i, j, k) += w * v;
              mass[a](i, j, k) += w;
            }
      }
    }
  };
  for (int phase = 0; phase < 2; ++phase)
    tbb::parallel_for(0, (slabs - phase + 1) / 2, [&](int t) { scatterSlab(2 * t + phase); });

  for (int a = 0; a < 3; ++a) {
    velocity[a] = Array3f(grid.faceCount(a), 0.0f);
    weight[a] = Array3f(grid.faceCount(a), 0.0f);
    auto& u = velocity[a].values();
    auto& wsum = weight[a].values();
    const auto& mom = momentum[a].values();
    const auto& ms = mass[a].values();
    tbb::parallel_for(std::size_t{0}, u.size(), [&](std::size_t f) {
      wsum[f] = static_cast<float>(ms[f]);
      u[f] = ms[f] > 0.0 ? static_cast<float>(mom[f] / ms[f]) : 0.0f;
    });
  }
}

Vec3 interpolateVelocity(const MacVelocity& velocity, const GridGeometry& grid, const Vec3& p) {
  const Vec3 g = grid.gridFromWorld(p);
  Vec3 out{};
  for (int a = 0; a < 3; ++a) {
    const Stencil st = faceStencil(g, a);
    const Array3f& u = velocity[a];
    double v = 0.0;
    for (int dk = 0; dk < 2; ++dk)
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di)
          v += (di ? st.frac[0] : 1 - st.frac[0]) * (dj ? st.frac[1] : 1 - st.frac[1]) *
               (dk ? st.frac[2] : 1 - st.frac[2]) * u.clamped(st.base[0] + di, st.base[1] + dj, st.base[2] + dk);
    out[a] = v;
  }
  return out;
}

void gridToParticles(Particles& particles, const MacVelocity& velocity, const MacVelocity& oldVelocity,
                     const GridGeometry& grid, const SolverSettings& settings) {
  const double h = grid.cellSize;
  tbb::parallel_for(std::size_t{0}, particles.size(), [&](std::size_t p) {
    const Vec3 x = toVec3(particles.position[p]);
    const Vec3 g = grid.gridFromWorld(x);
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
    for (int a = 0; a < 3; ++a) {
      const Stencil st = faceStencil(g, a);
      const Array3f& u = velocity[a];
      double v = 0.0, c[3] = {0.0, 0.0, 0.0};
      for (int dk = 0; dk < 2; ++dk)
        for (int dj = 0; dj < 2; ++dj)
          for (int di = 0; di < 2; ++di) {
            const double wx = di ? st.frac[0] : 1 - st.frac[0], wy = dj ? st.frac[1] : 1 - st.frac[1],
                         wz = dk ? st.frac[2] : 1 - st.frac[2];
            const double ui = u.clamped(st.base[0] + di, st.base[1] + dj, st.base[2] + dk);
            v += wx * wy * wz * ui;
            // ∇w of the trilinear weight [1/m] (Jiang et al. 2015, multilinear APIC).
            c[0] += (di ? 1.0 : -1.0) / h * wy * wz * ui;
            c[1] += (dj ? 1.0 : -1.0) / h * wx * wz * ui;
            c[2] += (dk ? 1.0 : -1.0) / h * wx * wy * ui;
          }
      particles.velocity[p][a] = static_cast<float>(v);
      particles.affine[p][a] = {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
    }
  });
}

}  // namespace fluidsound::sim
