// sim/fluid/particle_seeding.cpp — see particle_seeding.h.
#include "sim/fluid/particle_seeding.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "sim/fluid/random_stream.h"

namespace fluidsound::sim {

namespace {

double boxDistance(const Box& b, const Vec3& p) {
  // Exact signed distance to an axis-aligned box (negative inside).
  double outside = 0.0, inside = -1e300;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max(b.min[a] - p[a], p[a] - b.max[a]);
    outside += d > 0 ? d * d : 0.0;
    inside = std::max(inside, d);
  }
  return outside > 0 ? std::sqrt(outside) : inside;
}

}  // namespace

double regionDistance(const LiquidRegion& region, const Vec3& p, const MeshNodeDistance* mesh) {
  if (const auto* b = std::get_if<Box>(&region.shape)) return boxDistance(*b, p);
  if (const auto* s = std::get_if<Sphere>(&region.shape)) {
    const double dx = p[0] - s->center[0], dy = p[1] - s->center[1], dz = p[2] - s->center[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz) - s->radius;
  }
  if (mesh == nullptr)
    throw std::invalid_argument(std::get<MeshFile>(region.shape).file.string() +
                                ": the mesh's distance was not computed (sim::sceneMeshDistances)");
  return meshDistance(*mesh, p);
}

double meshDistance(const MeshNodeDistance& mesh, const Vec3& p) {
  return interpolateNodes(mesh.nodes, mesh.grid, p);
}

float interpolateNodes(const Array3f& nodes, const GridGeometry& grid, const Vec3& p) {
  const Vec3 g = grid.gridFromWorld(p);
  int i[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double c = std::clamp(g[a], 0.0, static_cast<double>(nodes.size()[a] - 1));
    // NaN passes the clamp; casting it to int is undefined (it gave INT_MIN and a read far out of
    // the array): node 0 instead, and the NaN weight makes the result NaN.
    i[a] = std::isnan(c) ? 0 : std::min(static_cast<int>(c), nodes.size()[a] - 2);
    f[a] = c - i[a];
  }
  double v = 0.0;
  for (int dk = 0; dk < 2; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di)
        v += (di ? f[0] : 1 - f[0]) * (dj ? f[1] : 1 - f[1]) * (dk ? f[2] : 1 - f[2]) *
             nodes(i[0] + di, i[1] + dj, i[2] + dk);
  return static_cast<float>(v);
}

namespace {
/// How far a stratified particle is jittered within its sub-cell, as a fraction of the
/// sub-cell: positions fill its middle half. Measured on a 16³ tank at rest (1 cm cells, max
/// particle speed at 2 s, with the density correction's dead band): 6.9 mm/s at full jitter
/// (1.0; the bumps of the seeded surface start gravity waves that decay with τ ≈ 1 s), 2.3 mm/s
/// at 0.5; at 0.3 the near-lattice clumps under flow (the coarse dam break thinned > 2 % of its
/// particles within 0.3 s), the known reason seeding is jittered at all.
constexpr double kStratumJitter = 0.5;
}  // namespace

Particles seedLiquid(const GridGeometry& grid, std::span<const LiquidRegion> regions,
                     const Array3f& solidNodeDistance, int perCell, std::uint64_t seed,
                     std::span<const MeshNodeDistance> regionMeshes) {
  std::vector<const MeshNodeDistance*> meshes;
  for (std::size_t r = 0; r < regions.size(); ++r)
    meshes.push_back(meshEntry(regions[r].shape, regionMeshes, r));
  const int ni = grid.cells[0], nj = grid.cells[1], nk = grid.cells[2];
  const int strata = static_cast<int>(std::lround(std::cbrt(perCell)));
  // Each cell seeds into its own slot; slots are concatenated in cell order (deterministic).
  std::vector<Particles> perSlab(static_cast<std::size_t>(nk));
  tbb::parallel_for(0, nk, [&](int k) {
    Particles& out = perSlab[k];
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i) {
        const std::uint64_t cell = (static_cast<std::uint64_t>(k) * nj + j) * ni + i;
        std::mt19937_64 random(cellStream(seed, cell));
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (int s = 0; s < perCell; ++s) {
          // Stratified when perCell is a cube (8 = 2³: one particle per sub-cell, jittered in the
          // middle of it), so the initial distribution has no clumps or holes; otherwise uniform.
          Vec3 local{unit(random), unit(random), unit(random)};
          if (strata * strata * strata == perCell) {
            const int sub[3] = {s % strata, (s / strata) % strata, s / (strata * strata)};
            for (int a = 0; a < 3; ++a) local[a] = (sub[a] + 0.5 + kStratumJitter * (local[a] - 0.5)) / strata;
          }
          const Vec3 p = grid.worldFromGrid({i + local[0], j + local[1], k + local[2]});
          if (interpolateNodes(solidNodeDistance, grid, p) <= 0.0f) continue;
          for (std::size_t n = 0; n < regions.size(); ++n) {
            const LiquidRegion& r = regions[n];
            if (regionDistance(r, p, meshes[n]) < 0.0) {
              out.push({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])},
                       {static_cast<float>(r.velocity[0]), static_cast<float>(r.velocity[1]),
                        static_cast<float>(r.velocity[2])});
              break;
            }
          }
        }
      }
  });
  return Particles::concatenate(perSlab);
}

}  // namespace fluidsound::sim
