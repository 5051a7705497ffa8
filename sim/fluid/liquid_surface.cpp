// sim/fluid/liquid_surface.cpp — see liquid_surface.h.
#include "sim/fluid/liquid_surface.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>

#include "sim/fluid/cell_interpolation.h"
#include "sim/fluid/particle_neighbourhoods.h"
#include "sim/fluid/particle_seeding.h"

namespace fluidsound::sim {
namespace {
constexpr double kKernelRadiusCells = 1.5;
/// Cells of full neighbourhood (each axis) that make a cell interior: 1 would do for the kernel
/// (its 3×3×3 cells), 2 keeps interior cells out of every interpolation that also touches a cell
/// next to the surface, so what reads φ in a uniform liquid gets the same bits as from the sum
/// (liquid_surface.h).
constexpr int kInteriorMarginCells = 2;

/// x if `keep`, else +0.0, without a branch. Adding the +0.0 (or +0.0 · x) to a sum started at
/// +0.0 leaves it bit for bit unchanged, so a skipped term and a zero term are the same.
double zeroUnless(bool keep, double x) {
  const std::uint64_t mask = std::uint64_t{0} - static_cast<std::uint64_t>(keep);
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) & mask);
}

/// The particles of the 3×3 rows of cells around one row of cells (fixed j, k), in sorted order,
/// in double, with their squared y and z distances to the row's cell centres precomputed (each
/// is shared by the row's cells). Rows ck outer, cj inner: the particles of cells
/// (i−1 … i+1, cj, ck) are then one contiguous range per row, in the order a cell-by-cell sum
/// visits them. Scratch reused from row to row.
struct NeighbourRows {
  std::vector<double> x, y, z, yy, zz;
  int rows = 0;
  std::size_t cell[9] = {};    ///< flat index of cell (0, cj, ck) of each neighbour row
  std::size_t offset[9] = {};  ///< array index of particle index.start[cell[r]]

  /// @return the number of particles gathered
  std::size_t gather(const Particles& particles, const CellIndex& index, const GridGeometry& grid, int j, int k) {
    const int ni = grid.cells[0], nj = grid.cells[1], nk = grid.cells[2];
    const Vec3 centre = grid.cellCentre(0, j, k);
    rows = 0;
    std::size_t total = 0;
    for (int ck = std::max(k - 1, 0); ck <= std::min(k + 1, nk - 1); ++ck)
      for (int cj = std::max(j - 1, 0); cj <= std::min(j + 1, nj - 1); ++cj, ++rows) {
        cell[rows] = (static_cast<std::size_t>(ck) * nj + cj) * ni;
        offset[rows] = total;
        total += index.start[cell[rows] + ni] - index.start[cell[rows]];
      }
    if (x.size() < total)
      for (auto* v : {&x, &y, &z, &yy, &zz}) v->resize(total);
    for (int r = 0; r < rows; ++r) {
      const std::size_t first = index.start[cell[r]], count = index.start[cell[r] + ni] - first;
      for (std::size_t q = 0; q < count; ++q) {
        const Vec3f& xp = particles.position[first + q];
        const std::size_t t = offset[r] + q;
        x[t] = xp[0], y[t] = xp[1], z[t] = xp[2];
        yy[t] = (centre[1] - xp[1]) * (centre[1] - xp[1]);
        zz[t] = (centre[2] - xp[2]) * (centre[2] - xp[2]);
      }
    }
    return total;
  }
};

}  // namespace

Array3f liquidDistanceFromParticles(const Particles& particles, const CellIndex& index,
                                    const GridGeometry& grid, double particleRadius, std::size_t interiorCount) {
  const int ni = grid.cells[0], nj = grid.cells[1], nk = grid.cells[2];
  // R = 1.5 h: the largest kernel the 3×3×3 cells around a cell centre contain; a smaller one
  // leaves dents where the jittered particles thin out.
  const double h = grid.cellSize, radius = kKernelRadiusCells * h, radius2 = radius * radius;
  Array3f phi(grid.cells, static_cast<float>(radius * kParticleSurfaceFarFactor));
  const Array3<std::uint8_t> interior =
      interiorCount > 0 ? particleNeighbourhoods(index, grid.cells, interiorCount, kInteriorMarginCells)
                        : Array3<std::uint8_t>(grid.cells, 0);
  tbb::parallel_for(0, nk, [&](int k) {
    NeighbourRows n;
    for (int j = 0; j < nj; ++j) {
      if (n.gather(particles, index, grid, j, k) == 0) continue;  // no liquid near this row
      const double *const px = n.x.data(), *const py = n.y.data(), *const pz = n.z.data();
      const double *const yy = n.yy.data(), *const zz = n.zz.data();
      for (int i = 0; i < ni; ++i) {
        if (interior(i, j, k) & kNeighbourhoodFull) {
          phi(i, j, k) = static_cast<float>(-particleRadius);
          continue;
        }
        const Vec3 x = grid.cellCentre(i, j, k);
        const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, ni - 1);
        double weight = 0.0, mean[3] = {0.0, 0.0, 0.0};
        for (int r = 0; r < n.rows; ++r) {
          const std::size_t first = index.start[n.cell[r]];
          const std::size_t end = index.start[n.cell[r] + i1 + 1] - first + n.offset[r];
          for (std::size_t p = index.start[n.cell[r] + i0] - first + n.offset[r]; p < end; ++p) {
            const double dx = x[0] - px[p];
            const double d2 = dx * dx + yy[p] + zz[p];
            const double s = 1.0 - d2 / radius2;
            // No branch: about half the candidates are beyond R, unpredictably.
            const double w = zeroUnless(d2 < radius2, s * s * s);
            weight += w;
            mean[0] += w * px[p];
            mean[1] += w * py[p];
            mean[2] += w * pz[p];
          }
        }
        if (weight <= 0.0) continue;
        double d2 = 0.0;
        for (int a = 0; a < 3; ++a) d2 += (x[a] - mean[a] / weight) * (x[a] - mean[a] / weight);
        phi(i, j, k) = static_cast<float>(std::sqrt(d2) - particleRadius);
      }
    }
  });
  return phi;
}

std::size_t fullCellParticles(int particlesPerCell) { return (static_cast<std::size_t>(particlesPerCell) + 1) / 2; }

Array3f solverSurfaceFromParticles(const Particles& particles, const CellIndex& index, const GridGeometry& grid,
                                   double particleRadius, int particlesPerCell) {
  Array3f phi =
      liquidDistanceFromParticles(particles, index, grid, particleRadius, fullCellParticles(particlesPerCell));
  // A cell holding 1.5× the seeding density is liquid whatever the kernel says: a sheet pressed
  // against a wall puts its particles within a sliver of the wall, where the kernel-averaged
  // surface would read the cell centre as air; as air it gets no pressure, gravity presses the
  // sheet harder, and the particles pile up (measured: a pour onto a floor thinned all its new
  // particles after the stream landed).
  constexpr double kCrowdedCellDepth = 0.1;  // φ given to a crowded cell [cells]: inside, a little below its centre
  const std::size_t crowded = (3 * static_cast<std::size_t>(particlesPerCell) + 1) / 2;
  const float inside = static_cast<float>(-kCrowdedCellDepth * grid.cellSize);
  auto& value = phi.values();
  for (std::size_t c = 0; c < value.size(); ++c)
    if (index.start[c + 1] - index.start[c] >= crowded) value[c] = std::min(value[c], inside);
  return phi;
}

double liquidVolume(const Array3f& phi, const GridGeometry& grid, const Array3f* solidNodes) {
  const double h = grid.cellSize;
  constexpr int kSamples = 4;                 // per axis and cell
  constexpr double kWidth = 1.0 / kSamples;   // sample spacing [cells]
  std::vector<double> perSlab(static_cast<std::size_t>(grid.cells[2]), 0.0);
  tbb::parallel_for(0, grid.cells[2], [&](int k) {
    double sum = 0.0;
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        const double centre = phi(i, j, k);
        if (centre >= h) continue;  // a cell away from the surface is all air…
        bool nearSolid = false;
        for (int c = 0; solidNodes != nullptr && c < 8 && !nearSolid; ++c)
          nearSolid = (*solidNodes)(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2)) < h;
        if (centre <= -h && !nearSolid) {  // …or all liquid
          sum += 1.0;
          continue;
        }
        const Vec3 corner = grid.worldFromGrid({double(i), double(j), double(k)});
        double fraction = 0.0;
        for (int s = 0; s < kSamples * kSamples * kSamples; ++s) {
          const Vec3 x{corner[0] + (s % kSamples + 0.5) * kWidth * h,
                       corner[1] + ((s / kSamples) % kSamples + 0.5) * kWidth * h,
                       corner[2] + (s / (kSamples * kSamples) + 0.5) * kWidth * h};
          if (nearSolid && interpolateNodes(*solidNodes, grid, x) <= 0.0f) continue;  // inside a solid
          fraction += std::clamp(0.5 - interpolateCellCentres(phi, grid, x) / (kWidth * h), 0.0, 1.0);
        }
        sum += fraction / (kSamples * kSamples * kSamples);
      }
    perSlab[k] = sum;
  });
  double cells = 0.0;
  for (double s : perSlab) cells += s;  // in slab order: the same sum for any thread count
  return cells * h * h * h;
}

}  // namespace fluidsound::sim
