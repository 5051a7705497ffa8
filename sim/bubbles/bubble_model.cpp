// sim/bubbles/bubble_model.cpp — see bubble_model.h.
#include "sim/bubbles/bubble_model.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sim/fluid/cell_interpolation.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/particle_transfer.h"
#include "sim/fluid/random_stream.h"

namespace fluidsound::sim {

namespace {

/// The bubble model's key under the scene seed ("BUBBLES!" in ASCII): its streams are unrelated
/// to the per-cell streams of particle seeding, which use cell indices as keys.
constexpr std::uint64_t kBubbleStreamKey = 0x425542424C455321ull;
/// Relative tolerance on step and frame times: they come from sums of substeps, so they may
/// differ from the expected time by rounding, never by more.
constexpr double kTimeTolerance = 1e-9;

/// Cells the surface band holds beyond the deepest (or highest) position a test reads (tagging
/// band + depth growth, or the largest radius; the tagging band in the air): a trilinear sample
/// reads the 8 centres around it, all within √3 ≈ 1.73 cells, so every centre a test reads holds
/// its distance to the nearest surface point, never the clamp. Deeper reads (SurfaceDistance::at
/// beyond band − 2 cells) search the surface points themselves.
constexpr double kSurfaceBandMarginCells = 1.75;

/// The grid velocity's range (velocity_range.h, about 3.5 ns per cell) is built only with at least
/// one particle per this many cells: it lets the entrainment skip speed tests (about 80 ns each)
/// that cannot pass, so with few particles (a glass pour: 2 500 in 41 000 cells, where it skipped
/// 260 of 1 700 tests per substep, 0.02 ms, for 0.14 ms of building) it costs more than it saves.
/// The decisions are the same with or without it.
constexpr std::size_t kCellsPerParticleForRange = 8;

/// Live bubbles per task of the motion: a drag solve takes about a microsecond, so a task of this
/// many outweighs its scheduling.
constexpr std::size_t kBubblesPerTask = 32;
/// Live bubbles per task of their end test: three interpolations each, tens of nanoseconds.
constexpr std::size_t kBubbleEndsPerTask = 512;

bool sameTime(double a, double b) {
  return std::abs(a - b) <= kTimeTolerance * std::max(1.0, std::abs(a));
}

bool insideGrid(const GridGeometry& grid, const Vec3& x) {
  const Vec3 g = grid.gridFromWorld(x);
  for (int a = 0; a < 3; ++a)
    if (!(g[a] >= 0.0 && g[a] <= grid.cells[a])) return false;
  return true;
}

bool sameLayout(const MacVelocity& a, const MacVelocity& b) {
  for (int c = 0; c < 3; ++c)
    if (a[c].size() != b[c].size()) return false;
  return true;
}

[[noreturn]] void rejectTime(const char* what, double got, double expected) {
  std::ostringstream message;
  message.precision(17);
  message << what << " must be the end of the previous step (" << expected << " s), got " << got
          << " s";
  throw std::invalid_argument(message.str());
}

}  // namespace

BubbleModel::BubbleModel(const BubbleSettings& settings, std::uint64_t seed, const Vec3& gravity)
    : settings_((validateBubbleSettings(settings), settings)),
      sizes_(settings.sizes),
      gravity_(gravity),
      streamRoot_(cellStream(seed, kBubbleStreamKey)) {
  for (double g : gravity)
    if (!std::isfinite(g)) {
      std::ostringstream message;
      message << "BubbleModel: gravity must be finite (m/s²), got " << g;
      throw std::invalid_argument(message.str());
    }
}

void BubbleModel::addBubble(double radius, double birth, const Vec3& position, double depth,
                            const LiquidState& liquid) {
  // The record's depth is the exact distance to the surface (the band field is clamped deeper).
  histories_.push_back({radius, birth, {{birth, position, -surface_.at(position)}}, std::nullopt});
  LiveBubble b;
  b.history = histories_.size() - 1;
  b.motion.position = position;
  b.motion.velocity = interpolateVelocity(liquid.velocity, liquid.grid, position);
  b.depth = depth;
  live_.push_back(b);
}

void BubbleModel::moveLiveBubbles(const LiquidState& solverState, double dt) {
  const GridGeometry& grid = solverState.grid;
  const bool hasPrevious = sameLayout(previousVelocity_, solverState.velocity);
  // Each bubble reads the shared fields and writes only its own slot: any thread count gives the
  // same result. A drag solve takes about a microsecond: tasks of kBubblesPerTask.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, live_.size(), kBubblesPerTask),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i) {
                        LiveBubble& b = live_[i];
                        const double radius = histories_[b.history].radius;
                        const Vec3 x = b.motion.position;
                        LiquidAtBubble at;
                        at.velocity = interpolateVelocity(solverState.velocity, grid, x);
                        if (hasPrevious) {
                          // Du/Dt ≈ (u(x, t + dt) − u(x − u·dt, t))/dt: the change along the
                          // liquid's path (semi-Lagrangian), which includes the advective part
                          // u·∇u.
                          const Vec3 back{x[0] - dt * at.velocity[0], x[1] - dt * at.velocity[1],
                                          x[2] - dt * at.velocity[2]};
                          const Vec3 before = interpolateVelocity(previousVelocity_, grid, back);
                          for (int a = 0; a < 3; ++a)
                            at.acceleration[a] = (at.velocity[a] - before[a]) / dt;
                        }
                        b.motion =
                            advanceBubble(b.motion, radius, at, gravity_, dt, settings_.rise);
                      }
                    });
}

void BubbleModel::endLiveBubbles(const LiquidState& liquid, double t, double dt,
                                 BubbleStepReport& report) {
  const GridGeometry& grid = liquid.grid;
  std::vector<Fate>& fate = fates_;
  std::vector<double>& deathTime = deathTimes_;
  fate.assign(live_.size(), Fate::Lives);
  deathTime.assign(live_.size(), 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, live_.size(), kBubbleEndsPerTask),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i) {
                        LiveBubble& b = live_[i];
                        const double radius = histories_[b.history].radius;
                        const Vec3& y = b.motion.position;
                        const double before = b.depth;
                        if (!insideGrid(grid, y)) {
                          fate[i] = Fate::Outside;
                          deathTime[i] = t + dt;
                          continue;
                        }
                        if (interpolateNodes(liquid.solidNodeDistance, grid, y) < 0.0f) {
                          fate[i] = Fate::Solid;
                          deathTime[i] = t + dt;
                          continue;
                        }
                        b.depth = -interpolateCellCentres(liquid.liquidDistance, grid, y);
                        if (b.depth <= radius) {
                          // The depth crossed the radius during the step: linear in time between
                          // the two depths.
                          const double fraction =
                              before > b.depth
                                  ? std::clamp((before - radius) / (before - b.depth), 0.0, 1.0)
                                  : 1.0;
                          fate[i] = Fate::Surface;
                          deathTime[i] = t + dt * fraction;
                        }
                      }
                    });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < live_.size(); ++i) {
    switch (fate[i]) {
      case Fate::Lives:
        live_[kept++] = live_[i];
        continue;
      case Fate::Surface:
        ++report.endedAtSurface;
        break;
      case Fate::Outside:
        ++report.endedOutside;
        break;
      case Fate::Solid:
        ++report.endedInSolid;
        break;
    }
    histories_[live_[i].history].death = deathTime[i];
  }
  live_.resize(kept);
}

void BubbleModel::rebuildDistance(const LiquidState& solverState) {
  const double h = solverState.grid.cellSize;
  // Depths are read down to the depth-growth test (or the largest radius); above the surface only
  // the tagging band is read (a particle in the air has no depth to grow, and bubbles are in the
  // liquid).
  const double read =
      std::max((settings_.bandCells + settings_.entrainmentDepthCells) * h, settings_.maxRadius());
  const double readInAir = settings_.bandCells * h;
  surface_.rebuild(solverState.liquidDistance, solverState.solidNodeDistance, solverState.grid,
                   read + kSurfaceBandMarginCells * h, readInAir + kSurfaceBandMarginCells * h);
}

LiquidState BubbleModel::withDistanceField(const LiquidState& solverState) const {
  return LiquidState{solverState.particlePositions,
                     solverState.particleVelocities,
                     solverState.particleIds,
                     surface_.field(),
                     solverState.velocity,
                     solverState.solidNodeDistance,
                     solverState.grid};
}

BubbleStepReport BubbleModel::step(const LiquidState& solverState, double t, double dt) {
  if (!(std::isfinite(dt) && dt > 0.0)) {
    std::ostringstream message;
    message << "BubbleModel::step: dt must be a finite number > 0 (seconds), got " << dt;
    throw std::invalid_argument(message.str());
  }
  if (!std::isfinite(t)) rejectTime("BubbleModel::step: t", t, stateTime_);
  if (steps_ > 0 && !sameTime(t, stateTime_)) rejectTime("BubbleModel::step: t", t, stateTime_);
  validateLiquidState(solverState);
  // The surface distance is rebuilt in a task while this thread moves the bubbles and bounds the
  // grid velocity, which read only the solver's state, and then takes the rebuild's own tasks at
  // wait(); with one thread the task runs there. Either way each result is computed as alone.
  tbb::task_group distance;
  distance.run([&] { rebuildDistance(solverState); });
  // (1) Move the bubbles made in earlier steps. Only they read the last step's grid velocity, so
  //     this step's is kept for the next one now, while the distance is still being rebuilt.
  moveLiveBubbles(solverState, dt);
  previousVelocity_ = solverState.velocity;
  const std::size_t cells = solverState.liquidDistance.values().size();
  if (entrainmentUsesVelocityRange(settings_) &&
      solverState.particlePositions.size() * kCellsPerParticleForRange >= cells)
    range_.emplace(solverState.velocity, solverState.grid);
  else
    range_.reset();
  distance.wait();
  const LiquidState liquid = withDistanceField(solverState);
  BubbleStepReport report;
  // ... and end those that reached the surface, left the grid or entered a solid.
  endLiveBubbles(liquid, t, dt, report);
  // (2) Tags and seeds at the end of the step.
  EntrainmentStep entrainment =
      detectEntrainment(liquid, tags_, settings_, t + dt, range_ ? &*range_ : nullptr);
  report.taggedParticles = entrainment.taggedParticles;
  report.newSeeds = entrainment.newSeeds;
  report.seeds = entrainment.seeds.size();
  // (3) New bubbles, from this step's own random stream.
  const SpawnResult spawned = spawnBubbles(entrainment.seeds, liquid, sizes_, settings_,
                                           {t, dt, cellStream(streamRoot_, steps_)});
  for (const SpawnedBubble& b : spawned.bubbles)
    addBubble(b.radius, b.birth, b.position, b.depth, liquid);
  report.spawn = spawned.counts;
  totals_ += spawned.counts;

  tags_ = std::move(entrainment.tags);
  seedCount_ = report.seeds;
  stateTime_ = t + dt;
  ++steps_;
  report.alive = live_.size();
  return report;
}

void BubbleModel::sampleFrame(double time) {
  if (!std::isfinite(time) || (steps_ > 0 && !sameTime(time, stateTime_)))
    rejectTime("BubbleModel::sampleFrame: time", time, stateTime_);
  for (const LiveBubble& b : live_) {
    std::vector<BubbleSample>& samples = histories_[b.history].samples;
    if (!samples.empty() && samples.back().time >= time) continue;
    samples.push_back({time, b.motion.position, -surface_.at(b.motion.position)});
  }
}

bool BubbleModel::insertBubble(double radius, const Vec3& position, double birth,
                               const LiquidState& solverState) {
  if (!(std::isfinite(radius) && radius > 0.0)) {
    std::ostringstream message;
    message << "BubbleModel::insertBubble: radius must be a finite number > 0 (metres), got "
            << radius;
    throw std::invalid_argument(message.str());
  }
  for (double c : position)
    if (!std::isfinite(c))
      throw std::invalid_argument("BubbleModel::insertBubble: position must be finite");
  if (!std::isfinite(birth))
    throw std::invalid_argument("BubbleModel::insertBubble: birth must be finite");
  validateLiquidState(solverState);
  rebuildDistance(solverState);
  const LiquidState liquid = withDistanceField(solverState);
  if (!insideGrid(liquid.grid, position)) return false;
  if (interpolateNodes(liquid.solidNodeDistance, liquid.grid, position) < radius) return false;
  const double depth = -interpolateCellCentres(liquid.liquidDistance, liquid.grid, position);
  if (!(depth > radius)) return false;
  addBubble(radius, birth, position, depth, liquid);
  return true;
}

}  // namespace fluidsound::sim
