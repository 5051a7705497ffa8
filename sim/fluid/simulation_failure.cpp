// sim/fluid/simulation_failure.cpp — see simulation_failure.h.
#include "sim/fluid/simulation_failure.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace fluidsound::sim {
namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

/// The lowest index in [0, count) for which `bad` holds, or kNone: the same on any thread count.
/// A template, not std::function: it runs over every particle and face each substep.
template <typename Bad>
std::size_t firstIndex(std::size_t count, const Bad& bad) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, count), kNone,
      [&](const tbb::blocked_range<std::size_t>& r, std::size_t found) {
        for (std::size_t i = r.begin(); i < r.end() && i < found; ++i)
          if (bad(i)) return i;
        return found;
      },
      [](std::size_t a, std::size_t b) { return a < b ? a : b; });
}

bool finite(const Vec3f& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

std::string timeText(double time) {
  char text[48];
  std::snprintf(text, sizeof text, "t = %.6f s", time);
  return text;
}

}  // namespace

std::string positionText(double x, double y, double z) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4f, %.4f, %.4f) m", x, y, z);
  return text;
}

void requireFiniteParticleVelocities(const Particles& particles, double time) {
  const std::size_t p =
      firstIndex(particles.size(), [&](std::size_t i) { return !finite(particles.velocity[i]); });
  if (p == kNone) return;
  const Vec3f& x = particles.position[p];
  const Vec3f& v = particles.velocity[p];
  char velocity[96];
  std::snprintf(velocity, sizeof velocity, "(%g, %g, %g) m/s", v[0], v[1], v[2]);
  throw SimulationFailure(timeText(time) + ": particle " + std::to_string(particles.id[p]) +
                          " at " + positionText(x[0], x[1], x[2]) + " has velocity " + velocity +
                          ": the solver blew up");
}

void requireTimeAdvances(const Particles& particles, double time, double dt) {
  if (time + dt > time) return;
  std::size_t fastest = 0;
  double fastest2 = -1.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double x = particles.velocity[p][0], y = particles.velocity[p][1],
                 z = particles.velocity[p][2];
    if (x * x + y * y + z * z > fastest2) fastest2 = x * x + y * y + z * z, fastest = p;
  }
  char step[64];
  std::snprintf(step, sizeof step, "the time step %.3g s no longer advances the clock", dt);
  std::string where;
  if (fastest2 >= 0.0) {
    const Vec3f& x = particles.position[fastest];
    char speed[48];
    std::snprintf(speed, sizeof speed, "%.3g m/s", std::sqrt(fastest2));
    where = ": particle " + std::to_string(particles.id[fastest]) + " at " +
            positionText(x[0], x[1], x[2]) + " moves at " + speed;
  }
  throw SimulationFailure(timeText(time) + ": " + step + where + ": the solver blew up");
}

void requireFiniteFaceVelocities(const MacVelocity& velocity, const GridGeometry& grid, double time,
                                 const char* stage) {
  for (int a = 0; a < 3; ++a) {
    const auto& u = velocity[a].values();
    const std::size_t f = firstIndex(u.size(), [&](std::size_t i) { return !std::isfinite(u[i]); });
    if (f == kNone) continue;
    const Index3 n = grid.faceCount(a);
    const int i = static_cast<int>(f % n[0]), j = static_cast<int>(f / n[0] % n[1]),
              k = static_cast<int>(f / (static_cast<std::size_t>(n[0]) * n[1]));
    Vec3 centre = grid.cellCentre(i, j, k);
    centre[a] -=
        0.5 * grid.cellSize;  // face (i, j, k) of axis a is the lower face of cell (i, j, k)
    throw SimulationFailure(
        timeText(time) + ": after the " + stage + " the velocity " + std::to_string(u[f]) +
        " m/s on the " + "xyz"[a] + "-face (" + std::to_string(i) + ", " + std::to_string(j) +
        ", " + std::to_string(k) + ") at " + positionText(centre[0], centre[1], centre[2]) +
        " is not finite: the solver blew up");
  }
}

}  // namespace fluidsound::sim
