// sim/fluid/particle_reseeding.cpp — see particle_reseeding.h.
#include "sim/fluid/particle_reseeding.h"

#include <algorithm>
#include <random>
#include <vector>

#include <tbb/parallel_for.h>

#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/random_stream.h"

namespace fluidsound::sim {

ReseedingCount reseedParticles(Particles& particles, const CellIndex& index,
                               const Array3f& liquidPhi, const MacVelocity& velocity,
                               const SolidBoundary& solids, const ReseedingPass& pass) {
  const GridGeometry& grid = solids.grid;
  const SolidMeshRays& meshes = *solids.meshes;
  const ReseedingLimits& limits = pass.limits;
  const int ni = grid.cells[0], nj = grid.cells[1], nk = grid.cells[2];
  const float inside = static_cast<float>(-0.5 * grid.cellSize);
  // Each slab k builds its part of the new particle list in cell order; slabs are joined in order.
  std::vector<Particles> perSlab(static_cast<std::size_t>(nk));
  std::vector<ReseedingCount> countPerSlab(static_cast<std::size_t>(nk));
  tbb::parallel_for(0, nk, [&](int k) {
    Particles& out = perSlab[k];
    ReseedingCount& count = countPerSlab[k];
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i) {
        const std::size_t cell = (static_cast<std::size_t>(k) * nj + j) * ni + i;
        const std::size_t first = index.start[cell], held = index.start[cell + 1] - first;
        const std::size_t keep = std::min<std::size_t>(held, limits.maximum);
        for (std::size_t p = first; p < first + keep; ++p) out.pushFrom(particles, p);
        count.removed += held - keep;
        if (held >= static_cast<std::size_t>(limits.minimum) || liquidPhi(i, j, k) > inside) continue;
        // An empty cell that a mesh wall cuts is not refilled: no particle tells which side is
        // liquid, and the cell's centre may lie inside the wall.
        if (held == 0 &&
            meshes.cutsBox(grid.worldFromGrid({double(i), double(j), double(k)}),
                           grid.worldFromGrid({i + 1.0, j + 1.0, k + 1.0}), pass.solidTime))
          continue;
        std::mt19937_64 random(cellStream(pass.seed ^ (pass.pass * 0xD1B54A32D192ED03ull), cell));
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (std::size_t n = held; n < static_cast<std::size_t>(limits.target); ++n) {
          const double u = unit(random), v = unit(random), w = unit(random);  // fixed draw order
          const Vec3 x = grid.worldFromGrid({i + u, j + v, k + w});
          if (interpolateNodes(solids.nodeDistance, grid, x) <= 0.0f) continue;
          // Not behind a mesh wall thinner than the cell, as seen from the cell's liquid.
          if (held > 0 && !meshes.empty()) {
            const Vec3 from{particles.position[first][0], particles.position[first][1], particles.position[first][2]};
            if (meshes.crosses(from, x, pass.solidTime)) continue;
          }
          const Vec3 vel = interpolateVelocity(velocity, grid, x);
          out.push({static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2])},
                   {static_cast<float>(vel[0]), static_cast<float>(vel[1]), static_cast<float>(vel[2])});
          ++count.added;
        }
      }
  });
  Particles all = Particles::concatenate(perSlab);
  ReseedingCount total;
  for (const ReseedingCount& c : countPerSlab) total.added += c.added, total.removed += c.removed;
  // Particles outside the grid (none in a closed box; sorted last) are kept as they are.
  const std::size_t cells = static_cast<std::size_t>(ni) * nj * nk;
  for (std::size_t p = index.start[cells]; p < particles.size(); ++p)
    all.pushFrom(particles, p);
  particles = std::move(all);
  return total;
}

}  // namespace fluidsound::sim
