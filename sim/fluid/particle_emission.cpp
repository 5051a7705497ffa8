// sim/fluid/particle_emission.cpp — see particle_emission.h.
#include "sim/fluid/particle_emission.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/random_stream.h"

namespace fluidsound::sim {
namespace {
/// Two unit vectors perpendicular to n and to each other (n need not be axis-aligned).
void tangentBasis(const Vec3& n, Vec3& u, Vec3& v) {
  const Vec3 helper = std::abs(n[0]) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  u = {n[1] * helper[2] - n[2] * helper[1], n[2] * helper[0] - n[0] * helper[2], n[0] * helper[1] - n[1] * helper[0]};
  const double length = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& c : u) c /= length;
  v = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
}

/// Whether x lies in the grid's box (its faces included).
bool insideGrid(const GridGeometry& grid, const Vec3& x) {
  for (int a = 0; a < 3; ++a) {
    const double lo = grid.origin[a], hi = grid.origin[a] + grid.cells[a] * grid.cellSize;
    if (!(x[a] >= lo && x[a] <= hi)) return false;
  }
  return true;
}
}  // namespace

double emittedVolume(const Emitter& emitter, double a, double b) {
  const double active = std::max(0.0, std::min(b, emitter.end) - std::max(a, emitter.start));
  return std::numbers::pi * emitter.radius * emitter.radius * emitter.speed * active;
}

std::size_t emitParticles(Particles& particles, const Emitter& emitter, EmitterState& state,
                          double t0, double t1, const EmissionSetting& setting) {
  const GridGeometry& grid = setting.grid;
  const int perCell = setting.perCell;
  const double from = std::max(t0, emitter.start), to = std::min(t1, emitter.end);
  if (!(to > from)) return 0;
  const double h = grid.cellSize;
  state.owed += emittedVolume(emitter, t0, t1) * perCell / (h * h * h);
  const auto count = static_cast<std::size_t>(std::floor(state.owed));
  state.owed -= static_cast<double>(count);
  Vec3 u, v;
  tangentBasis(emitter.normal, u, v);
  std::size_t appended = 0;
  for (std::size_t q = 0; q < count; ++q) {
    // One generator per particle, keyed by the emitter and the draw number: the same particles
    // whatever the substeps' lengths were before.
    std::mt19937_64 random(cellStream(
        setting.seed ^ (0xA24BAED4963EE407ull * (setting.emitterIndex + 1)), state.draws++));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double instant = from + (to - from) * unit(random);
    const double radius = emitter.radius * std::sqrt(unit(random));
    const double angle = 2.0 * std::numbers::pi * unit(random);
    const double along = emitter.speed * (t1 - instant);
    Vec3 x;
    for (int a = 0; a < 3; ++a)
      x[a] = emitter.center[a] + along * emitter.normal[a] + radius * (std::cos(angle) * u[a] + std::sin(angle) * v[a]);
    ++state.emitted;
    if (!insideGrid(grid, x)) continue;  // the part of the disk (or the flow) beyond the domain
    if (interpolateNodes(setting.solidNodes, grid, x) <= 0.0f) continue;
    const float s = static_cast<float>(emitter.speed);
    particles.push({static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2])},
                   {s * static_cast<float>(emitter.normal[0]), s * static_cast<float>(emitter.normal[1]),
                    s * static_cast<float>(emitter.normal[2])});
    ++appended;
  }
  return appended;
}

}  // namespace fluidsound::sim
