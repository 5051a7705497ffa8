// sim/cache_bubbles.cpp — see cache_bubbles.h.
#include "sim/cache_bubbles.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include <tbb/task_group.h>

#include "sim/bubbles/bubble_model.h"
#include "sim/fluid/liquid_surface.h"
#include "sim/fluid/particle_transfer.h"
#include "sim/fluid/scene_mesh_distances.h"
#include "sim/fluid/solid_boundary.h"
#include "sim/fluid/solid_geometry.h"
#include "sim/fluid/solid_mesh_rays.h"
#include "sim/fluid/velocity_extrapolation.h"
#include "sim/particle_matching.h"
#include "sim/particle_paths.h"

namespace fluidsound::sim {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

[[noreturn]] void reject(int frame, const std::string& what) {
  throw std::invalid_argument("cacheBubbles: frame " + std::to_string(frame) + ": " + what);
}

/// The seeding density the solver's surface rules assume of a cache (its own default).
constexpr int kCacheParticlesPerCell = 8;
/// Cells around the particles' box whose surface value they may change: the kernel's reach (1.5
/// cells, from the 3×3×3 cells around a centre) rounded up, plus one for a particle on a cell edge.
constexpr int kSurfaceReachCells = 3;

/// How far [cells] a particle of the next frame may lie from a particle's advected place and still
/// be that particle: a splash moves a particle a cell or two off the grid's prediction in a frame
/// (measured on a falling column at 30 fps: 1 cell found 62 % of the bubbles the ids give, 2 cells
/// 95 %).
constexpr double kMatchRadiusCells = 2.0;

/// Layers of faces the velocity is extended by beyond the cache's (the solver's ceil(CFL) + 2).
constexpr int kVelocityExtensionLayers = 3;

/// Checks a frame's arrays against the grid and fills what the cache may leave out: particle
/// velocities (the grid velocity at each particle).
void completeFrame(LiquidFrame& frame, int index, const GridGeometry& grid, const SolidBoundary& solids) {
  if (frame.liquidDistance.size() != grid.cells) reject(index, "its level set does not fit the grid");
  for (int a = 0; a < 3; ++a)
    if (frame.velocity[a].size() != grid.faceCount(a)) reject(index, "its velocity does not fit the grid");
  // The velocity beyond what the cache gives, as the solver's beyond the liquid: the same number
  // of layers (its CFL 1 plus 2), so that a test near the liquid's edge or a wall reads the
  // liquid's velocity there, not the cache's background 0.
  if (frame.velocityKnown[0].elementCount() > 0) {
    for (int a = 0; a < 3; ++a)
      if (frame.velocityKnown[a].size() != grid.faceCount(a)) reject(index, "its velocity mask does not fit the grid");
    extrapolateVelocity(frame.velocity, frame.velocityKnown, kVelocityExtensionLayers);
  }
  constrainToSolids(frame.velocity, solids);
  FrameParticles& p = frame.particles;
  if (!p.id.empty() && p.id.size() != p.size()) reject(index, "its particle ids do not match its particles");
  if (p.velocity.empty()) {
    p.velocity.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 u = interpolateVelocity(frame.velocity, grid, {p.position[i][0], p.position[i][1], p.position[i][2]});
      p.velocity[i] = {static_cast<float>(u[0]), static_cast<float>(u[1]), static_cast<float>(u[2])};
    }
  } else if (p.velocity.size() != p.size()) {
    reject(index, "its particle velocities do not match its particles");
  }
}

float largestFaceSpeed(const MacVelocity& u) {
  float largest = 0.0f;
  for (int a = 0; a < 3; ++a)
    for (float v : u[a].values()) largest = std::max(largest, std::abs(v));
  return largest;
}

/// `out` = (1 − α)·a + α·b, element by element.
void blend(const Array3f& a, const Array3f& b, float alpha, Array3f& out) {
  if (out.size() != a.size()) out = Array3f(a.size());
  const float* x = a.data();
  const float* y = b.data();
  float* z = out.data();
  for (std::size_t i = 0; i < a.elementCount(); ++i) z[i] = x[i] + alpha * (y[i] - x[i]);
}

/// φ of the particles' own surface, as the solver makes it (solverSurfaceFromParticles) with radius
/// r [m]. Sorts `particles` by cell (the bubble model reads them in any order).
void particleSurface(Particles& particles, const GridGeometry& grid, double radius, Array3f& phi) {
  // Made on the part of the grid the particles reach (their box and the kernel's 2 cells around
  // it, one more for rounding); air elsewhere, as the whole grid's pass would give: a pour fills a
  // fraction of its domain.
  phi = Array3f(grid.cells, static_cast<float>(radius * kParticleSurfaceFarFactor));
  if (particles.size() == 0) return;
  Index3 lo{grid.cells}, hi{-1, -1, -1};
  for (const Vec3f& x : particles.position) {
    const Vec3 g = grid.gridFromWorld({x[0], x[1], x[2]});
    for (int a = 0; a < 3; ++a) {
      const int c = static_cast<int>(std::floor(g[a]));
      lo[a] = std::min(lo[a], c), hi[a] = std::max(hi[a], c);
    }
  }
  GridGeometry part = grid;
  Index3 first{};
  for (int a = 0; a < 3; ++a) {
    first[a] = std::clamp(lo[a] - kSurfaceReachCells, 0, grid.cells[a] - 1);
    const int last = std::clamp(hi[a] + kSurfaceReachCells, 0, grid.cells[a] - 1);
    if (last < first[a]) return;  // every particle outside the grid
    part.cells[a] = last - first[a] + 1;
    part.origin[a] = grid.origin[a] + first[a] * grid.cellSize;
  }
  particles.affine.assign(particles.size(), {});
  const CellIndex index = sortParticlesByCell(particles, part);
  const Array3f own = solverSurfaceFromParticles(particles, index, part, radius, kCacheParticlesPerCell);
  for (int k = 0; k < part.cells[2]; ++k)
    for (int j = 0; j < part.cells[1]; ++j)
      for (int i = 0; i < part.cells[0]; ++i) phi(first[0] + i, first[1] + j, first[2] + k) = own(i, j, k);
}

/// The particles of one frame that are also in the next: index in each.
struct ParticlePairs {
  std::vector<std::uint32_t> from, to;
};

ParticlePairs pairsById(std::span<const std::uint64_t> a, std::span<const std::uint64_t> b) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> sorted(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) sorted[i] = {a[i], static_cast<std::uint32_t>(i)};
  std::sort(sorted.begin(), sorted.end());
  ParticlePairs pairs;
  for (std::size_t j = 0; j < b.size(); ++j) {
    const auto at = std::lower_bound(sorted.begin(), sorted.end(), std::make_pair(b[j], std::uint32_t{0}));
    if (at == sorted.end() || at->first != b[j]) continue;
    pairs.from.push_back(at->second);
    pairs.to.push_back(static_cast<std::uint32_t>(j));
  }
  return pairs;
}

/// The scene's solids and the closed faces of its domain on the grid at a time (solid_boundary.h,
/// as the solver has them).
class ImportSolids {
 public:
  ImportSolids(const Scene& scene, const GridGeometry& grid)
      : scene_(scene), grid_(grid), rays_(scene.solids), meshes_(sceneMeshDistances(scene, grid)),
        domain_(scene.domain) {
    for (const Solid& s : scene.solids) moving_ = moving_ || !s.path.empty();
    at_ = solidBoundaryAt(grid_, domain_, scene_.solids, rays_, 0.0, meshes_.solids);
  }
  const SolidBoundary& at(double time) {
    if (moving_) at_ = solidBoundaryAt(grid_, domain_, scene_.solids, rays_, time, meshes_.solids);
    return at_;
  }

 private:
  const Scene& scene_;
  const GridGeometry& grid_;
  SolidMeshRays rays_;
  SceneMeshDistances meshes_;
  Domain domain_;
  bool moving_ = false;
  SolidBoundary at_;
};

}  // namespace

CacheBubbleResult cacheBubbles(LiquidFrameSource& source, const GridGeometry& grid, const Scene& scene,
                               const CacheImportSettings& settings, CacheBubbleObserver& observer) {
  const int count = source.frameCount();
  if (count < 2) throw std::invalid_argument("cacheBubbles: a cache needs at least 2 frames, got " + std::to_string(count));
  if (!(settings.particleRadiusCells > 0.0 && settings.cfl > 0.0 && settings.perEntrainmentWindow >= 1 &&
        settings.maxPerFrame >= 1))
    throw std::invalid_argument("cacheBubbles: particleRadiusCells and cfl must be > 0, perEntrainmentWindow and "
                                "maxPerFrame >= 1");
  observer.started(count);
  BubbleModel bubbles(scene.bubbles, scene.seed, scene.gravity);
  ImportSolids solids(scene, grid);
  CacheBubbleResult result;

  // Frame f + 1 is read while the bubble model steps towards frame f: a task of the caller's TBB
  // arena, so with one thread it runs when waited for, and the frames' order and bits are the
  // same for any thread count. Every path out of the loop waits for it (task_group's rule).
  tbb::task_group reading;
  std::optional<LiquidFrame> ahead;
  const auto readAhead = [&](int f) {
    if (f < count) reading.run([&ahead, &source, f] { ahead = source.frame(f); });
  };
  const auto takeAhead = [&] {
    reading.wait();  // rethrows the read's error
    LiquidFrame frame = std::move(*ahead);
    ahead.reset();
    return frame;
  };

  auto t0 = Clock::now();
  readAhead(0);
  LiquidFrame previous = takeAhead();
  readAhead(1);
  completeFrame(previous, 0, grid, solids.at(previous.time));
  // A frame has the cache's ids when it has one per particle (a frame without particles has them
  // all); otherwise its particles are found in the frame before by their advected positions.
  const auto hasIds = [](const LiquidFrame& frame) { return frame.particles.id.size() == frame.particles.size(); };
  std::uint64_t nextId = 0;
  if (!hasIds(previous)) {
    previous.particles.id.resize(previous.particles.size());
    for (std::uint64_t& id : previous.particles.id) id = nextId++;
  } else {
    for (std::uint64_t id : previous.particles.id) nextId = std::max(nextId, id + 1);
  }
  CacheFrameRecord first{0, previous.time, previous.particles.size(), 0, 0, 0, 0, secondsSince(t0), 0.0};
  result.readSeconds += first.readSeconds;
  observer.onFrame(previous, first);
  result.frames.push_back(first);
  observer.progress(1.0 / count);

  const double h = grid.cellSize;
  Array3f phi;
  MacVelocity velocity(grid);
  Particles substep;  // the particles at a substep's end (sorted by cell when the surface is made)
  for (int f = 1; f < count; ++f) {
    if (observer.wasInterrupted()) {
      reading.wait();
      result.interruptedAt = f;
      break;
    }
    t0 = Clock::now();
    LiquidFrame next = takeAhead();
    readAhead(f + 1);
    completeFrame(next, f, grid, solids.at(next.time));
    CacheFrameRecord record;
    record.frame = f;
    record.time = next.time;
    record.particles = next.particles.size();
    record.readSeconds = secondsSince(t0);
    const double interval = next.time - previous.time;
    if (!(interval > 0.0)) reject(f, "its time does not follow the frame before's");
    // The particles' ids: the cache's, or their nearest advected positions'.
    if (!hasIds(next)) {
      const std::vector<Vec3f> predicted =
          carriedPositions(previous.particles.position, previous.velocity, next.velocity, grid, interval);
      next.particles.id =
          matchParticleIds(predicted, previous.particles.id, next.particles.position, kMatchRadiusCells * h, nextId);
    } else {
      for (std::uint64_t id : next.particles.id) nextId = std::max(nextId, id + 1);
    }
    const ParticlePairs pairs = pairsById(previous.particles.id, next.particles.id);
    record.followed = pairs.to.size();

    t0 = Clock::now();
    double reach = interval * std::max(largestFaceSpeed(previous.velocity), largestFaceSpeed(next.velocity));
    for (std::size_t i = 0; i < pairs.to.size(); ++i) {
      const Vec3f& a = previous.particles.position[pairs.from[i]];
      const Vec3f& b = next.particles.position[pairs.to[i]];
      reach = std::max(reach, std::sqrt(double((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                                               (b[2] - a[2]) * (b[2] - a[2]))));
    }
    const int byWindow = static_cast<int>(
        std::ceil(interval * settings.perEntrainmentWindow / scene.bubbles.entrainmentWindow - 1e-9));
    const int n = std::clamp(std::max(static_cast<int>(std::ceil(reach / (settings.cfl * h))), byWindow), 1,
                             settings.maxPerFrame);
    record.substeps = n;
    for (int s = 0; s < n; ++s) {
      const double t = previous.time + interval * s / n;
      const bool last = s + 1 == n;  // the frame itself, with every particle it holds
      const double end = last ? next.time : previous.time + interval * (s + 1) / n;
      const MacVelocity* u = &next.velocity;
      if (last) {
        substep.position = next.particles.position;
        substep.velocity = next.particles.velocity;
        substep.id = next.particles.id;
      } else {
        const auto alpha = static_cast<float>(static_cast<double>(s + 1) / n);
        for (int a = 0; a < 3; ++a) blend(previous.velocity[a], next.velocity[a], alpha, velocity[a]);
        u = &velocity;
        substep.position.resize(pairs.to.size());
        substep.velocity.resize(pairs.to.size());
        substep.id.resize(pairs.to.size());
        for (std::size_t i = 0; i < pairs.to.size(); ++i) {
          const std::uint32_t from = pairs.from[i], to = pairs.to[i];
          const PathPoint p = hermitePath(previous.particles.position[from], previous.particles.velocity[from],
                                          next.particles.position[to], next.particles.velocity[to], interval,
                                          static_cast<double>(s + 1) / n);
          substep.position[i] = p.position;
          substep.velocity[i] = p.velocity;
          substep.id[i] = next.particles.id[to];
        }
      }
      particleSurface(substep, grid, settings.particleRadiusCells * h, phi);
      bubbles.step(LiquidState{substep.position, substep.velocity, substep.id, phi, *u, solids.at(end).nodeDistance,
                               grid},
                   t, end - t);
    }
    bubbles.sampleFrame(next.time);
    record.bubbleSeconds = secondsSince(t0);
    record.bubblesAlive = bubbles.aliveCount();
    record.bubblesTotal = bubbles.bubbles().size();
    result.readSeconds += record.readSeconds;
    result.bubbleSeconds += record.bubbleSeconds;
    observer.onFrame(next, record);
    result.frames.push_back(record);
    observer.progress(static_cast<double>(f + 1) / count);
    previous = std::move(next);
  }
  result.bubbles = bubbles.bubbles();
  return result;
}

}  // namespace fluidsound::sim
