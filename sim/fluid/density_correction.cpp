// sim/fluid/density_correction.cpp — see density_correction.h.
#include "sim/fluid/density_correction.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>

#include "sim/fluid/cell_interpolation.h"
#include "sim/fluid/particle_advection.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/velocity_extrapolation.h"

namespace fluidsound::sim {
namespace {
/// Density deviations |ρ/ρ₀ − ρ_expected| up to this are left alone [-]: the correction is for
/// clumps and holes (excess ≥ 1 in wall corners, measured), not for the ±0.1–0.2 that jittered
/// particles read anyway; correcting those moved every particle every frame and kept a tank at
/// rest in motion (16³ tank at rest, max speed at 2 s: 2.3 mm/s with the band, 16.9 without,
/// at the seeding jitter of particle_seeding.cpp).
constexpr double kDensityDeadBand = 0.25;

/// Cells of displacement extended beyond the liquid: particles near the surface read D there.
constexpr int kExtendedLayers = 2;
/// Depth [cells] below which every sample of expectedDensity reads all liquid: a sample is 1 from
/// φ ≤ −h/4 on, and the samples interpolate the 27 centres around the cell; the extra 0.05 h
/// keeps rounding in the interpolation away from that edge. The 64 weights sum to 1 exactly
/// (dyadic), so returning 1 gives the bits the samples would.
constexpr double kSaturatedDepthCells = 0.3;

/// Whether φ ≤ `below` at the 27 centres around (i, j, k) (indices clamped to the grid, as the
/// interpolation clamps them).
bool surroundedBy(const Array3f& phi, int i, int j, int k, double below) {
  const Index3& n = phi.size();
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di)
        if (phi(std::clamp(i + di, 0, n[0] - 1), std::clamp(j + dj, 0, n[1] - 1), std::clamp(k + dk, 0, n[2] - 1)) >
            below)
          return false;
  return true;
}

/// ρ/ρ₀ that relativeParticleDensity would read at cell (i, j, k) for particles spread evenly
/// through the liquid that φ describes, outside the scene's solids: the tent-weighted liquid
/// fraction of the cell's tent support [−h, h]³, from 4 × 4 × 4 samples (each 0.5 h wide, liquid
/// fraction clamp(½ − φ/(0.5 h), 0, 1) × clamp(½ + d_solid/(0.5 h), 0, 1)). 1 deep inside, 0 far
/// outside; 7/8 half a cell below a flat surface or beside a flat solid wall. Correcting against
/// it, not against 1, leaves a uniform liquid's surface alone and keeps the liquid as dense
/// against a solid as anywhere (a solid then displaces its own volume, not more).
/// @param solidCentre  the scene solids' distance at the cell centre [m]
double expectedDensity(const Array3f& phi, const Array3f& sceneSolidNodes, double solidCentre,
                       const GridGeometry& grid, const Index3& cell) {
  const int i = cell[0], j = cell[1], k = cell[2];
  const double h = grid.cellSize, value = phi(i, j, k);
  const bool nearSolid = solidCentre < 1.5 * h;
  if (value <= -1.5 * h && !nearSolid) return 1.0;
  if (value >= 1.5 * h) return 0.0;
  if (!nearSolid && surroundedBy(phi, i, j, k, -kSaturatedDepthCells * h)) return 1.0;  // every sample 1
  constexpr double offset[4] = {-0.75, -0.25, 0.25, 0.75}, weight[4] = {0.125, 0.375, 0.375, 0.125};
  const Vec3 centre = grid.cellCentre(i, j, k);
  double sum = 0.0;
  for (int c = 0; c < 64; ++c) {
    const int a = c & 3, b = (c >> 2) & 3, d = c >> 4;
    const Vec3 x{centre[0] + offset[a] * h, centre[1] + offset[b] * h, centre[2] + offset[d] * h};
    double liquid = std::clamp(0.5 - interpolateCellCentres(phi, grid, x) / (0.5 * h), 0.0, 1.0);
    if (nearSolid) liquid *= std::clamp(0.5 + interpolateNodes(sceneSolidNodes, grid, x) / (0.5 * h), 0.0, 1.0);
    sum += weight[a] * weight[b] * weight[d] * liquid;
  }
  return sum;
}
}  // namespace

namespace {
/// The trilinear (tent) weight along one axis of a particle at x for the centre c of cell `cell`
/// of `cells` [-]. A particle between the first (last) centre and the grid boundary gives it the
/// weight the missing centre beyond would get, so a uniform liquid against a wall reads 1 there
/// too (else 7/8 per wall, and the thin-out correction would pull particles into walls and
/// corners).
double tentWeight(double x, double c, int cell, int cells, double h) {
  const bool folded = (cell == 0 && x < c) || (cell == cells - 1 && x > c);
  return folded ? 1.0 : std::max(0.0, 1.0 - std::abs(x - c) / h);
}
}  // namespace

Array3f relativeParticleDensity(const Particles& particles, const CellIndex& index, const GridGeometry& grid,
                                int perCell) {
  const int ni = grid.cells[0], nj = grid.cells[1], nk = grid.cells[2];
  const double h = grid.cellSize;
  Array3f density(grid.cells, 0.0f);
  // One slab of centres (fixed k) per task; the particles of the cells around it are visited
  // cell by cell in sorted order and add their weight to the 3 × 3 centres around their cell.
  // Each centre thus sums its particles in sorted order, the order a per-centre gather would
  // use, on any thread count.
  tbb::parallel_for(0, nk, [&](int k) {
    std::vector<double> sum(static_cast<std::size_t>(ni) * nj, 0.0);
    const double cz = grid.cellCentre(0, 0, k)[2];
    for (int ck = std::max(k - 1, 0); ck <= std::min(k + 1, nk - 1); ++ck)
      for (int cj = 0; cj < nj; ++cj)
        for (int ci = 0; ci < ni; ++ci) {
          const std::size_t cell = (static_cast<std::size_t>(ck) * nj + cj) * ni + ci;
          for (std::size_t p = index.start[cell]; p < index.start[cell + 1]; ++p) {
            const Vec3f& x = particles.position[p];
            const double wz = tentWeight(x[2], cz, k, nk, h);
            if (wz == 0.0) continue;
            for (int j = std::max(cj - 1, 0); j <= std::min(cj + 1, nj - 1); ++j) {
              const double wy = tentWeight(x[1], grid.cellCentre(0, j, 0)[1], j, nj, h);
              if (wy == 0.0) continue;
              for (int i = std::max(ci - 1, 0); i <= std::min(ci + 1, ni - 1); ++i) {
                const double wx = tentWeight(x[0], grid.cellCentre(i, 0, 0)[0], i, ni, h);
                sum[static_cast<std::size_t>(j) * ni + i] += wx * wy * wz;
              }
            }
          }
        }
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i)
        density(i, j, k) = static_cast<float>(sum[static_cast<std::size_t>(j) * ni + i] / perCell);
  });
  return density;
}

DensityCorrectionReport correctParticleDensity(Particles& particles, const CellIndex& index,
                                               const DensityCorrectionInput& liquid,
                                               const SolidBoundary& solids, PressureSolver& solver,
                                               const PressureSettings& settings) {
  const GridGeometry& grid = solids.grid;
  const Array3f& pressurePhi = liquid.pressurePhi;
  const Array3f& sceneSolidNodes = solids.sceneNodeDistance;
  const int perCell = liquid.perCell;
  DensityCorrectionReport report;
  const Array3f density = relativeParticleDensity(particles, index, grid, perCell);
  Array3f strain(grid.cells, 0.0f);  // target divergence of D [-] (D in metres, "Δt" = 1)
  std::vector<double> maxExcessOfSlab(static_cast<std::size_t>(grid.cells[2]), 0.0);
  tbb::parallel_for(0, grid.cells[2], [&](int k) {
    double& maxExcess = maxExcessOfSlab[k];
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        const double phi = pressurePhi(i, j, k);
        if (phi >= 0.0) continue;
        double solid = 0.0;  // solid distance at the centre: mean of the 8 nodes [m]
        for (int c = 0; c < 8; ++c) solid += sceneSolidNodes(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2));
        solid /= 8.0;
        if (solid <= 0.0) continue;  // a cell inside a solid holds no particles by design
        const double excess =
            density(i, j, k) -
            expectedDensity(liquid.particlePhi, sceneSolidNodes, solid, grid, {i, j, k});
        const double banded = excess > kDensityDeadBand    ? excess - kDensityDeadBand
                              : excess < -kDensityDeadBand ? excess + kDensityDeadBand
                                                           : 0.0;
        strain(i, j, k) = static_cast<float>(banded);
        maxExcess = std::max(maxExcess, excess);  // (deficits beside solids too: see expectedDensity)
      }
  });
  for (double m : maxExcessOfSlab) report.maxExcess = std::max(report.maxExcess, m);
  MacVelocity displacement(grid);
  const std::array<Array3f, 3> noSolidMotion{Array3f(grid.faceCount(0), 0.0f), Array3f(grid.faceCount(1), 0.0f),
                                             Array3f(grid.faceCount(2), 0.0f)};
  // With "density" 1 and "Δt" 1 the projection's update is D −= ∇q/h·h: a displacement in metres.
  report.solve = solver.project(displacement,
                                PressureProblem{pressurePhi, solids.faceOpen, noSolidMotion, grid,
                                                /*density=*/1.0, /*dt=*/1.0, &strain},
                                settings);
  extrapolateVelocity(displacement, solver.validFaces(), kExtendedLayers);
  for (int a = 0; a < 3; ++a) {  // no displacement through walls
    auto& d = displacement[a].values();
    const auto& open = solids.faceOpen[a].values();
    for (std::size_t f = 0; f < d.size(); ++f)
      if (open[f] <= 0.0f) d[f] = 0.0f;
  }
  report.particlesDeleted = advectParticles(particles, displacement, solids,
                                            SolidTimes{liquid.solidTime, liquid.solidTime}, 1.0);
  return report;
}

}  // namespace fluidsound::sim
