// sim/fluid/liquid_level_set.cpp — see liquid_level_set.h.
#include "sim/fluid/liquid_level_set.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>
#include <vector>

#include "sim/fluid/cell_interpolation.h"
#include "sim/fluid/liquid_surface.h"
#include "sim/fluid/particle_neighbourhoods.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/solid_geometry.h"

namespace fluidsound::sim {
namespace {

/// φ where nothing is known: far from every region, as the particle surface's far value.
constexpr double kFarCells = 8.0;
/// φ a cell is held to where the particles leave no doubt [cells]: within half a cell of its
/// centre on the liquid (every cell around full) or the air (no particle around) side.
constexpr double kCertainCells = 0.5;
/// Passes of extendLevelAcrossSolids: the corner of two walls off the cell planes takes three
/// (tests/sim/fluid/liquid_level_set_test.cpp); a fully closed cell deeper in the solid is no unknown of
/// the pressure solve, whatever it holds.
constexpr int kExtensionPasses = 3;

/// Whether the cell's centre lies inside a solid (the solver's rule for solid cells).
bool centreInSolid(const Array3f& solidNodes, int i, int j, int k) {
  return cellCentreSolidDistance(solidNodes, i, j, k) < 0.0f;
}

/// Signed distance [m] from x to the free faces of box b: outside it, the distance to the box;
/// inside, the distance to the nearest face that lies neither on the grid's boundary (a closed
/// wall, or an open face the liquid runs on through) nor against a solid — its foot point (x
/// projected on the face) more than kSolidContactCells from one (`solidNodes`). Water poured
/// into a tank up to its walls, or overlapping them, has no surface there: its level is y − H
/// right up to the wall, as in the middle (the box's own distance would read the wall cells up
/// to half a cell shallower, a slope the pressure solve turns into a flow). kFarCells·h deep
/// where no face is free.
double freeBoxDistance(const Box& b, const Vec3& x, const Array3f& solidNodes,
                       const GridGeometry& grid) {
  const double outside = regionDistance(LiquidRegion{b, {}}, x);
  if (outside > 0.0) return outside;
  const double contact = kSolidContactCells * grid.cellSize;
  double depth = kFarCells * grid.cellSize;
  for (int a = 0; a < 3; ++a) {
    const double lowest = grid.origin[a] + contact,
                 highest = grid.origin[a] + grid.cells[a] * grid.cellSize - contact;
    for (const double plane : {b.min[a], b.max[a]}) {
      if (plane <= lowest || plane >= highest) continue;  // on the grid's boundary
      Vec3 foot = x;
      foot[a] = plane;
      if (interpolateNodes(solidNodes, grid, foot) <= contact) continue;
      depth = std::min(depth, std::abs(x[a] - plane));
    }
  }
  return -depth;
}

/// The signed distance [m] from the centre of `cell` (i, j, k) to the free faces of region r
/// (`mesh`: its node distance when it is a mesh, else null).
double freeRegionDistance(const LiquidRegion& r, const MeshNodeDistance* mesh, const Index3& cell,
                          const Array3f& solidNodes, const GridGeometry& grid) {
  const auto [i, j, k] = cell;
  const Vec3 x = grid.cellCentre(i, j, k);
  if (const auto* box = std::get_if<Box>(&r.shape))
    return freeBoxDistance(*box, x, solidNodes, grid);
  if (mesh != nullptr && mesh->freeSurfaceAtCentres.size() == grid.cells)
    return mesh->freeSurfaceAtCentres(i, j, k);
  return regionDistance(r, x, mesh);
}
}  // namespace

double liquidVolumeOutsideSolids(const Array3f& phi, const Array3f& sceneSolidNodes,
                                 const GridGeometry& grid) {
  return liquidVolume(phi, grid, &sceneSolidNodes);
}

LiquidLevelSet::LiquidLevelSet(const FluidScene& scene, const GridGeometry& grid,
                               const Array3f& solidNodes,
                               std::span<const MeshNodeDistance> regionMeshes)
    : grid_(grid), phi_(grid.cells, static_cast<float>(kFarCells * grid.cellSize)) {
  if (scene.liquid.empty()) return;
  std::vector<const MeshNodeDistance*> meshes;
  for (std::size_t r = 0; r < scene.liquid.size(); ++r)
    meshes.push_back(meshEntry(scene.liquid[r].shape, regionMeshes, r));
  tbb::parallel_for(0, grid.cells[2], [&](int k) {
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        const Vec3 x = grid.cellCentre(i, j, k);
        double region = kFarCells * grid.cellSize;
        for (std::size_t r = 0; r < scene.liquid.size(); ++r)
          region = std::min(
              region, freeRegionDistance(scene.liquid[r], meshes[r], {i, j, k}, solidNodes, grid));
        // Inside a solid: air (the solid's own depth), the solid holds no liquid.
        const double solid = interpolateNodes(solidNodes, grid, x);
        phi_(i, j, k) = static_cast<float>(solid < 0.0 ? std::max(region, -solid) : region);
      }
  });
}

void LiquidLevelSet::holdToParticles(const Array3f& particlePhi, const CellIndex& index,
                                     const MacVelocity& velocity, const Array3f& sceneSolidNodes,
                                     const LevelSetHold& hold) {
  const Index3 n = grid_.cells;
  const double h = grid_.cellSize;
  // Over the 3 × 3 × 3 block around each cell: all full, or any particle at all.
  const Array3<std::uint8_t> flags =
      particleNeighbourhoods(index, n, static_cast<std::size_t>(hold.fullCount), 1);
  tbb::parallel_for(0, n[2], [&](int k) {
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        float& phi = phi_(i, j, k);
        const float particle = particlePhi(i, j, k);
        if (std::isnan(phi)) {  // carried out of a solid: the particles say
          phi = particle;
          continue;
        }
        const std::uint8_t around = flags(i, j, k);
        if (around & kNeighbourhoodFull) {  // every cell around full
          phi = std::min(phi, static_cast<float>(-kCertainCells * h));
          continue;
        }
        if (!(around & kNeighbourhoodAny)) {  // no particle around
          phi = std::max(phi, static_cast<float>(kCertainCells * h));
          continue;
        }
        const double ux = 0.5 * (velocity[0](i, j, k) + velocity[0](i + 1, j, k));
        const double uy = 0.5 * (velocity[1](i, j, k) + velocity[1](i, j + 1, k));
        const double uz = 0.5 * (velocity[2](i, j, k) + velocity[2](i, j, k + 1));
        const double speed = std::sqrt(ux * ux + uy * uy + uz * uz);
        const double band =
            hold.bandCells * h * std::clamp(1.0 - speed / hold.trustSpeed, 0.0, 1.0);
        phi = std::clamp(phi, static_cast<float>(particle - band),
                         static_cast<float>(particle + band));
      }
  });
  keepSolidsDry(sceneSolidNodes);
}

void LiquidLevelSet::keepSolidsDry(const Array3f& sceneSolidNodes) {
  tbb::parallel_for(0, grid_.cells[2], [&](int k) {
    for (int j = 0; j < grid_.cells[1]; ++j)
      for (int i = 0; i < grid_.cells[0]; ++i) {
        if (!centreInSolid(sceneSolidNodes, i, j, k)) continue;
        const double solid = interpolateNodes(sceneSolidNodes, grid_, grid_.cellCentre(i, j, k));
        if (solid < 0.0) phi_(i, j, k) = std::max(phi_(i, j, k), static_cast<float>(-solid));
      }
  });
}

void LiquidLevelSet::advect(const MacVelocity& velocity, const Array3f& sceneSolidNodes, double dt,
                            double bandCells) {
  Array3f next = phi_;
  const float band = static_cast<float>(bandCells * grid_.cellSize);
  tbb::parallel_for(0, grid_.cells[2], [&](int k) {
    for (int j = 0; j < grid_.cells[1]; ++j)
      for (int i = 0; i < grid_.cells[0]; ++i) {
        if (std::abs(phi_(i, j, k)) >= band)
          continue;  // far from the surface: only its sign counts
        const Vec3 x = grid_.cellCentre(i, j, k);
        const Vec3 u0 = interpolateVelocity(velocity, grid_, x);
        const Vec3 mid{x[0] - 0.5 * dt * u0[0], x[1] - 0.5 * dt * u0[1], x[2] - 0.5 * dt * u0[2]};
        const Vec3 u1 = interpolateVelocity(velocity, grid_, mid);
        const Vec3 from{x[0] - dt * u1[0], x[1] - dt * u1[1], x[2] - dt * u1[2]};
        next(i, j, k) = interpolateNodes(sceneSolidNodes, grid_, from) < 0.0f
                            ? std::numeric_limits<float>::quiet_NaN()
                            : static_cast<float>(interpolateCellCentres(phi_, grid_, from));
      }
  });
  phi_ = std::move(next);
}

void LiquidLevelSet::matchVolume(double target, const Array3f& sceneSolidNodes) {
  const double h = grid_.cellSize;
  // Cells carried out of a solid (NaN until the next hold) count as air here.
  Array3f known = phi_;
  std::size_t surfaceCells = 0;
  for (float& phi : known.values()) {
    if (std::isnan(phi)) phi = static_cast<float>(kFarCells * h);
    surfaceCells += std::abs(phi) < 0.5 * h;
  }
  if (surfaceCells == 0) return;
  const double shift =
      std::clamp((liquidVolumeOutsideSolids(known, sceneSolidNodes, grid_) - target) /
                     (static_cast<double>(surfaceCells) * h * h),
                 -kCertainCells * h, kCertainCells * h);
  for (float& phi : phi_.values()) phi = static_cast<float>(phi + shift);  // NaN stays NaN
  keepSolidsDry(sceneSolidNodes);
}

Array3f extendLevelAcrossSolids(const Array3f& phi, const Array3f& solidNodes, const Index3& up,
                                double h) {
  const Index3 n = phi.size();
  const int upAxis = up[0] != 0 ? 0 : up[1] != 0 ? 1 : 2;
  Array3<std::uint8_t> solid(n, 0),
      known(n, 0);  // centre inside a solid; φ known (outside or filled)
  tbb::parallel_for(0, n[2], [&](int k) {
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        solid(i, j, k) = centreInSolid(solidNodes, i, j, k);
        known(i, j, k) = !solid(i, j, k);
      }
  });
  Array3f out = phi;
  // Passes after the first fill the solid cells whose horizontal neighbours are all solid but
  // were filled by an earlier one — the corner of two walls that both lie off the cell planes
  // (up to three cells there), where particles stopped at the walls would otherwise sit in a
  // cell the pressure solve sees as air.
  for (int pass = 0; pass < kExtensionPasses; ++pass) {
    const Array3f from = out;
    const Array3<std::uint8_t> knownBefore = known;
    tbb::parallel_for(0, n[2], [&](int k) {
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          if (knownBefore(i, j, k)) continue;
          double sum = 0.0;
          int count = 0;
          for (int a = 0; a < 3; ++a) {
            if (a == upAxis) continue;
            for (const int side : {-1, 1}) {
              Index3 c{i, j, k};
              c[a] += side;
              if (c[a] < 0 || c[a] >= n[a] || !knownBefore(c[0], c[1], c[2])) continue;
              sum += from(c[0], c[1], c[2]);
              ++count;
            }
          }
          if (count > 0) {
            out(i, j, k) = static_cast<float>(sum / count);
            known(i, j, k) = 1;
            continue;
          }
          // Under (over) a known cell: one cell deeper (higher) than it.
          for (const int side : {1, -1}) {
            const Index3 c{i + side * up[0], j + side * up[1], k + side * up[2]};
            if (c[upAxis] < 0 || c[upAxis] >= n[upAxis] || !knownBefore(c[0], c[1], c[2])) continue;
            out(i, j, k) = static_cast<float>(from(c[0], c[1], c[2]) - side * h);
            known(i, j, k) = 1;
            break;
          }
        }
    });
  }
  return out;
}

}  // namespace fluidsound::sim
