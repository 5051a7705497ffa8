// sim/liquid_surface.cpp — see liquid_surface.h.
#include "sim/liquid_surface.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace fluidsound::sim {
namespace {
/// φ far from any particle, as a multiple of the kernel radius: only the sign and the values
/// next to the surface matter to the ghost-fluid pressure solve.
constexpr double kFarFactor = 1.0;
constexpr double kKernelRadiusCells = 1.5;
}  // namespace

Array3f liquidDistanceFromParticles(const Particles& particles, const CellIndex& index,
                                    const GridGeometry& grid, double particleRadius) {
  const int ni = grid.cells[0], nj = grid.cells[1], nk = grid.cells[2];
  // R = 1.5 h: the largest kernel the 3×3×3 cells around a cell centre contain; a smaller one
  // leaves dents where the jittered particles thin out.
  const double h = grid.cellSize, radius = kKernelRadiusCells * h, radius2 = radius * radius;
  Array3f phi(grid.cells, static_cast<float>(radius * kFarFactor));
  tbb::parallel_for(0, nk, [&](int k) {
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i) {
        const Vec3 x = grid.cellCentre(i, j, k);
        double weight = 0.0, mean[3] = {0.0, 0.0, 0.0};
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              const int ci = i + di, cj = j + dj, ck = k + dk;
              if (ci < 0 || cj < 0 || ck < 0 || ci >= ni || cj >= nj || ck >= nk) continue;
              const std::size_t c = (static_cast<std::size_t>(ck) * nj + cj) * ni + ci;
              for (std::size_t p = index.start[c]; p < index.start[c + 1]; ++p) {
                const Vec3f& xp = particles.position[p];
                const double d2 = (x[0] - xp[0]) * (x[0] - xp[0]) + (x[1] - xp[1]) * (x[1] - xp[1]) +
                                  (x[2] - xp[2]) * (x[2] - xp[2]);
                if (d2 >= radius2) continue;
                const double s = 1.0 - d2 / radius2, w = s * s * s;
                weight += w;
                for (int a = 0; a < 3; ++a) mean[a] += w * xp[a];
              }
            }
        if (weight <= 0.0) continue;
        double d2 = 0.0;
        for (int a = 0; a < 3; ++a) d2 += (x[a] - mean[a] / weight) * (x[a] - mean[a] / weight);
        phi(i, j, k) = static_cast<float>(std::sqrt(d2) - particleRadius);
      }
  });
  return phi;
}

double liquidVolume(const Array3f& phi, const GridGeometry& grid) {
  const double h = grid.cellSize;
  double fraction = 0.0;
  for (float v : phi.values()) fraction += std::clamp(0.5 - v / h, 0.0, 1.0);
  return fraction * h * h * h;
}

}  // namespace fluidsound::sim
