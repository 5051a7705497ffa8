// sim/fluid/particle_advection.cpp — see particle_advection.h.
#include "sim/fluid/particle_advection.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/particle_transfer.h"

namespace fluidsound::sim {
namespace {
/// How far outside a solid a pushed-out particle lands, in cells: enough that interpolation
/// error of the nodal distance does not leave it inside.
constexpr double kSolidMargin = 0.05;
/// Half-width of the finite difference for the solid distance gradient, in cells.
constexpr double kGradientStep = 0.25;
}  // namespace

std::size_t advectParticles(Particles& particles, const MacVelocity& velocity,
                            const SolidBoundary& solids, const SolidTimes& times, double dt) {
  const GridGeometry& grid = solids.grid;
  const Domain& domain = solids.domain;
  const SolidMeshRays& meshes = *solids.meshes;
  const double h = grid.cellSize;
  const Array3f& solidNodeDistance = solids.nodeDistance;
  std::vector<std::uint8_t> keep(particles.size(), 1);
  tbb::parallel_for(std::size_t{0}, particles.size(), [&](std::size_t p) {
    const Vec3 x{particles.position[p][0], particles.position[p][1], particles.position[p][2]};
    const Vec3 u0 = interpolateVelocity(velocity, grid, x);
    const Vec3 mid{x[0] + 0.5 * dt * u0[0], x[1] + 0.5 * dt * u0[1], x[2] + 0.5 * dt * u0[2]};
    const Vec3 u1 = interpolateVelocity(velocity, grid, mid);
    Vec3 y{x[0] + dt * u1[0], x[1] + dt * u1[1], x[2] + dt * u1[2]};
    if (const auto stop =
            meshes.firstCrossing(x, y, times.from, times.to, kMeshWallOffsetCells * h)) {
      y = stop->position;
      Vec3f& v = particles.velocity[p];
      double into = 0.0;  // velocity towards the wall, relative to it [m/s] (normal faces the particle)
      for (int a = 0; a < 3; ++a) into += (v[a] - stop->wallVelocity[a]) * stop->normal[a];
      if (into < 0.0)
        for (int a = 0; a < 3; ++a) v[a] = static_cast<float>(v[a] - into * stop->normal[a]);
      // The affine part described the flow around a particle moving with it; a stopped one keeps
      // it no longer. Kept, it wrote v + C·d onto faces reached by no other particle, read them
      // back into a larger C, and a particle stuck in the glass pour's floor corner at 2.5 mm cells
      // doubled its speed every three substeps until it was infinite (docs/solver.md).
      particles.affine[p] = {};
    }
    for (int a = 0; a < 3; ++a) {
      if (domain.open[2 * a] && y[a] < domain.min[a]) keep[p] = 0;
      if (domain.open[2 * a + 1] && y[a] > domain.max[a]) keep[p] = 0;
      const double margin = kSolidMargin * h;
      y[a] = std::clamp(y[a], domain.min[a] + margin, domain.max[a] - margin);
    }
    const double d = interpolateNodes(solidNodeDistance, grid, y);
    if (d < 0.0) {
      Vec3 gradient{};
      double norm = 0.0;
      for (int a = 0; a < 3; ++a) {
        Vec3 lo = y, hi = y;
        lo[a] -= kGradientStep * h;
        hi[a] += kGradientStep * h;
        gradient[a] = interpolateNodes(solidNodeDistance, grid, hi) - interpolateNodes(solidNodeDistance, grid, lo);
        norm += gradient[a] * gradient[a];
      }
      norm = std::sqrt(norm);
      Vec3 pushed = y;
      if (norm > 0.0)
        for (int a = 0; a < 3; ++a) pushed[a] += (-d + kSolidMargin * h) * gradient[a] / norm;
      if (!meshes.crosses(y, pushed, times.to)) {
        y = pushed;
        if (norm > 0.0) {  // no velocity into the wall it was pushed back from (as at a mesh wall)
          Vec3f& v = particles.velocity[p];
          double into = 0.0;
          for (int a = 0; a < 3; ++a) into += v[a] * gradient[a] / norm;
          if (into < 0.0)
            for (int a = 0; a < 3; ++a) v[a] = static_cast<float>(v[a] - into * gradient[a] / norm);
        }
      }
    }
    particles.position[p] = {static_cast<float>(y[0]), static_cast<float>(y[1]), static_cast<float>(y[2])};
  });
  // Remove the deleted, keeping the order (nothing to move when no domain face is open).
  if (std::find(keep.begin(), keep.end(), std::uint8_t{0}) == keep.end()) return 0;
  std::size_t kept = 0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (!keep[p]) continue;
    particles.move(p, kept);
    ++kept;
  }
  const std::size_t deleted = particles.size() - kept;
  particles.resize(kept);
  return deleted;
}

}  // namespace fluidsound::sim
