// sim/fluid/fluid_solver.cpp — see fluid_solver.h.
#include "sim/fluid/fluid_solver.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <variant>

#include "sim/fluid/density_correction.h"
#include "sim/fluid/liquid_surface.h"
#include "sim/fluid/particle_advection.h"
#include "sim/fluid/particle_emission.h"
#include "sim/fluid/particle_reseeding.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/particle_transfer.h"
#include "sim/fluid/pressure_solver.h"
#include "sim/fluid/simulation_failure.h"
#include "sim/fluid/solid_boundary.h"
#include "sim/fluid/solid_geometry.h"
#include "sim/fluid/solid_mesh_rays.h"
#include "sim/fluid/thin_wall_faces.h"
#include "sim/fluid/velocity_extrapolation.h"

namespace fluidsound::sim {
namespace {
/// Layers of face velocity extrapolated beyond the liquid: a particle moves at most `cfl` cells
/// per substep and reads velocities one cell around it.
constexpr int kExtraLayers = 2;
/// Substeps are cut so that none is shorter than this fraction of the previous: avoids a tiny last
/// substep before a frame boundary (the remainder is split evenly over two substeps instead).
constexpr double kMinimumSubstepFraction = 0.25;
/// Relative residual of the once-per-frame density correction's solve: it repeats every frame, so
/// a loose solve suffices (5–8 multigrid-CG iterations).
constexpr double kDensityCorrectionTolerance = 1e-3;
/// φ below which a cut cell under liquid counts as liquid for the pressure solve [cells]
/// (extendIntoSolids): above the |φ| ≤ 0.06 h measured in under-seeded corner cells.
constexpr double kCutCellSurfaceLimit = 0.1;
/// Speed [cells/s] from which the level set follows the particles alone (LevelSetHold::trustSpeed):
/// 0.1 m/s at 1 cm cells. Still and slowly moving liquid (a tank, a settling pool) keeps the
/// level set's surface; a pour or a surge, the particles'.
constexpr double kTrustSpeedCellsPerSecond = 10.0;
/// Cells beyond the CFL number in which the level set is advected (LiquidLevelSet::advect): the
/// band the surface can reach in a substep, plus the cells the interpolation next to it reads.
constexpr double kLevelSetMarginCells = 3.0;

/// The liquid distance the pressure solve sees: extended into cells whose centre is inside a solid
/// and that touch the liquid (the cell or a face neighbour has φ < 0: φ = −h/2 there, after
/// Batty's Fluid3D `compute_phi`), so no free surface forms against a wall and cut cells next to
/// walls drain nothing. Solid cells that touch no liquid — the part of a sloped floor or a sphere
/// above the water line — stay air: marking them liquid would carry the free surface up along
/// the solid's face and drive currents at the contact line (measured: a sphere piercing the
/// surface of a still tank, 13–23 cm/s with every solid cell liquid).
/// Also extended: a cell cut by a solid (a corner inside it) whose φ < h/10 and whose neighbour
/// against gravity (`up`) is liquid or such a cut cell itself — a cell under liquid, against a
/// wall. In a corner between a slope and a wall the trilinear nodal distance reads more of the
/// cell as solid than it is, seeding and reseeding leave it short of particles, and its φ reads
/// as a free surface (|φ| < 0.06 h) at the bottom of the tank: measured 10–30 cm/s in a tank
/// with a 15° floor, 2.9 mm/s with this rule. Along a wall off the node planes the cut cells of
/// a column read φ ≈ 0 one above the other, hence "or such a cut cell". The topmost cut cell,
/// at a contact line, has air above it and is left alone.
Array3f extendIntoSolids(const Array3f& liquidPhi, const SolidBoundary& solids, const Index3& up) {
  const Array3f& solidNodes = solids.nodeDistance;
  const GridGeometry& grid = solids.grid;
  Array3f phi = liquidPhi;
  const float inside = static_cast<float>(-0.5 * grid.cellSize);
  // A cell a solid cuts (a corner inside it) whose φ reads no higher than just above its centre.
  const auto wetCutCell = [&](const Index3& c) {
    if (liquidPhi(c[0], c[1], c[2]) >= kCutCellSurfaceLimit * grid.cellSize) return false;
    for (int n = 0; n < 8; ++n)
      if (solidNodes(c[0] + (n & 1), c[1] + ((n >> 1) & 1), c[2] + (n >> 2)) < 0.0f) return true;
    return false;
  };
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        if (cellCentreSolidDistance(solidNodes, i, j, k) >= 0.0f) {
          const Index3 above{i + up[0], j + up[1], k + up[2]};
          if (wetCutCell({i, j, k}) && liquidPhi.contains(above[0], above[1], above[2]) &&
              (liquidPhi(above[0], above[1], above[2]) < 0.0f || wetCutCell(above)))
            phi(i, j, k) = std::min(phi(i, j, k), inside);
          continue;
        }
        bool touchesLiquid = liquidPhi(i, j, k) < 0.0f;
        for (int a = 0; a < 3 && !touchesLiquid; ++a)
          for (int side : {-1, 1}) {
            Index3 n{i, j, k};
            n[a] += side;
            if (liquidPhi.contains(n[0], n[1], n[2]) && liquidPhi(n[0], n[1], n[2]) < 0.0f) touchesLiquid = true;
          }
        if (touchesLiquid) phi(i, j, k) = inside;
      }
  return phi;
}

/// The grid step against gravity: the axis along which |g| is largest, pointing up.
Index3 upFromGravity(const Vec3& gravity) {
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(gravity[a]) > std::abs(gravity[axis])) axis = a;
  Index3 up{0, 0, 0};
  up[axis] = gravity[axis] > 0.0 ? -1 : 1;
  return up;
}
}  // namespace

struct FluidSolver::Workspace {
  /// The solids at the current time (rebuilt at every substep's end time when solids move).
  SolidBoundary solids;
  std::array<Array3f, 3> weight;        ///< particle weight per face (P2G)
  MacVelocity oldVelocity;              ///< grid velocity before forces (FLIP)
  TransferWorkspace transfer;           ///< sort and particle → grid buffers, reused every substep
  FaceMask reached;                     ///< faces particles reached (P2G weight > 0)
  PressureSolver pressure;
  SolidMeshRays meshWalls;              ///< ray queries against the mesh solids (thin walls)
  SceneMeshDistances meshes;            ///< the mesh solids' and regions' distances on the grid
  std::vector<EmitterState> emitters;   ///< one per scene emitter
  bool solidsMove = false;
};

void FluidSolver::extendSolidPath(std::size_t solid, std::span<const PathKey> keys) {
  if (solid >= scene_.solids.size() || scene_.solids[solid].path.empty())
    throw std::invalid_argument("FluidSolver::extendSolidPath: solid " + std::to_string(solid) +
                                " is not a solid with a path");
  std::vector<PathKey>& path = scene_.solids[solid].path;
  for (const PathKey& key : keys)
    if (!(key.time > path.back().time))
      throw std::invalid_argument("FluidSolver::extendSolidPath: keys must come after the path's last");
    else
      path.push_back(key);
  work_->meshWalls.extendPath(solid, keys);
}

FluidSolver::FluidSolver(const FluidScene& scene, FluidProperties properties)
    : scene_(scene), properties_(properties), grid_(scene.grid()), work_(std::make_unique<Workspace>()) {
  work_->meshes = sceneMeshDistances(scene, grid_);
  work_->emitters.resize(scene.emitters.size());
  for (const Solid& s : scene.solids) work_->solidsMove = work_->solidsMove || !s.path.empty();
  work_->meshWalls = SolidMeshRays(scene.solids);
  work_->solids =
      solidBoundaryAt(grid_, scene.domain, scene.solids, work_->meshWalls, 0.0, work_->meshes.solids);
  const int perCell = scene.solver.particlesPerCell;
  particles_ = seedLiquid(grid_, scene.liquid, work_->solids.nodeDistance, perCell, scene.seed,
                          work_->meshes.liquid);
  assignParticleIds(particles_.id, nextParticleId_);
  // 0.8 × the mean particle spacing h/∛n: centres the Zhu–Bridson surface of a seeded layer on
  // the layer's top (measured in tests/sim/fluid/particle_transfer_test.cpp).
  constexpr double kRadiusOverSpacing = 0.8;
  particleRadius_ = kRadiusOverSpacing * grid_.cellSize / std::cbrt(static_cast<double>(perCell));
  velocity_ = MacVelocity(grid_);
  const CellIndex& index = sortParticlesByCell(particles_, grid_, work_->transfer);
  particlesToGrid(particles_, grid_, scene.solver.transfer, velocity_, work_->weight, work_->transfer);
  liquidPhi_ = surfaceFromParticles(index);
  if (usesLevelSet()) {
    levelSet_ = LiquidLevelSet(scene, grid_, work_->solids.nodeDistance, work_->meshes.liquid);
    levelSet_.holdToParticles(liquidPhi_, index, velocity_, work_->solids.sceneNodeDistance,
                              levelSetHold());
    liquidPhi_ = levelSet_.phi();
    liquidVolumeTarget_ =
        liquidVolumeOutsideSolids(liquidPhi_, work_->solids.sceneNodeDistance, grid_);
  }
}

std::size_t FluidSolver::fullCellCount() const {
  return fullCellParticles(scene_.solver.particlesPerCell);
}

double FluidSolver::liquidVolume() const {
  return liquidVolumeOutsideSolids(liquidPhi_, work_->solids.sceneNodeDistance, grid_);
}

bool FluidSolver::usesLevelSet() const { return scene_.solver.surface == SurfaceMethod::LevelSet; }

LevelSetHold FluidSolver::levelSetHold() const {
  LevelSetHold hold;
  hold.trustSpeed = kTrustSpeedCellsPerSecond * grid_.cellSize;
  hold.fullCount = static_cast<int>(fullCellCount());
  return hold;
}

FluidSolver::~FluidSolver() = default;

Array3f FluidSolver::surfaceFromParticles(const CellIndex& index) const {
  return solverSurfaceFromParticles(particles_, index, grid_, particleRadius_, scene_.solver.particlesPerCell);
}

void FluidSolver::maintainParticles(FrameStats& stats) {
  Workspace& w = *work_;
  // 1. Spread clumps and fill thin spots by moving particles (positions only).
  const CellIndex& before = sortParticlesByCell(particles_, grid_, w.transfer);
  const Array3f particlePhi = surfaceFromParticles(before);
  PressureSettings settings;
  settings.tolerance = kDensityCorrectionTolerance;
  settings.maxIterations = scene_.solver.maxPressureIterations;
  const Array3f pressurePhi =
      extendIntoSolids(particlePhi, w.solids, upFromGravity(scene_.gravity));
  const DensityCorrectionReport correction = correctParticleDensity(
      particles_, before,
      DensityCorrectionInput{pressurePhi, particlePhi, scene_.solver.particlesPerCell, time_},
      w.solids, w.pressure, settings);
  stats.particlesDeleted += correction.particlesDeleted;
  stats.densityIterations += correction.solve.iterations;
  stats.maxDensityExcess = std::max(stats.maxDensityExcess, correction.maxExcess);
  // 2. Refill liquid cells left with too few particles and thin what is still clumped. The particle
  //    surface from before the correction decides which cells are liquid (the correction moves
  //    particles by a fraction of a cell).
  const CellIndex& after = sortParticlesByCell(particles_, grid_, w.transfer);
  if (usesLevelSet()) {
    // The level set held to the particles as each substep holds it, then given the liquid's volume.
    levelSet_.holdToParticles(particlePhi, after, velocity_, w.solids.sceneNodeDistance,
                              levelSetHold());
    const double particleVolume = std::pow(grid_.cellSize, 3) / scene_.solver.particlesPerCell;
    liquidVolumeTarget_ +=
        (static_cast<double>(stats.particlesEmitted) - static_cast<double>(leftThroughOpenFaces_)) * particleVolume;
    levelSet_.matchVolume(liquidVolumeTarget_, w.solids.sceneNodeDistance);
    liquidPhi_ = levelSet_.phi();
  } else {
    liquidPhi_ = particlePhi;
  }
  leftThroughOpenFaces_ = 0;
  ReseedingLimits limits;
  limits.target = scene_.solver.particlesPerCell;
  limits.minimum = std::min(limits.minimum, limits.target);
  limits.maximum = std::max(limits.maximum, 2 * limits.target);
  const ReseedingCount count =
      reseedParticles(particles_, after, particlePhi, velocity_, w.solids,
                      ReseedingPass{limits, scene_.seed, ++reseedPasses_, time_});
  assignParticleIds(particles_.id, nextParticleId_);
  stats.particlesReseeded += count.added;
  stats.particlesThinned += count.removed;
}

double FluidSolver::stableTimeStep() const {
  requireFiniteParticleVelocities(particles_, time_);
  // Bridson (2015) §3.3: u_max = max|u_p| + √(5 h |g|) bounds the speed reached in one step.
  const double speed2 = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, particles_.size()), 0.0,
      [&](const tbb::blocked_range<std::size_t>& r, double m) {
        for (std::size_t p = r.begin(); p < r.end(); ++p) {
          const Vec3f& v = particles_.velocity[p];
          m = std::max(m, static_cast<double>(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
        }
        return m;
      },
      [](double a, double b) { return std::max(a, b); });  // max is exact: order does not matter
  const Vec3& g = scene_.gravity;
  const double gravity = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  double emitterSpeed = 0.0;  // particles about to leave a nozzle move at its speed
  for (const Emitter& e : scene_.emitters)
    if (time_ < e.end) emitterSpeed = std::max(emitterSpeed, e.speed);
  const double speed = std::max(std::sqrt(speed2), emitterSpeed) + std::sqrt(5.0 * grid_.cellSize * gravity);
  const double dt = speed > 0.0 ? scene_.time.cfl * grid_.cellSize / speed : 1e300;
  requireTimeAdvances(particles_, time_, dt);
  return dt;
}

SubstepLimitError FluidSolver::substepLimitError(double until, double dt) const {
  float particleSpeed2 = 0.0f;
  for (const Vec3f& v : particles_.velocity) particleSpeed2 = std::max(particleSpeed2, v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const double particleSpeed = std::sqrt(static_cast<double>(particleSpeed2));
  double emitterSpeed = 0.0, initialSpeed = 0.0;
  for (const Emitter& e : scene_.emitters) emitterSpeed = std::max(emitterSpeed, e.speed);
  for (const LiquidRegion& r : scene_.liquid)
    initialSpeed = std::max(initialSpeed, std::sqrt(r.velocity[0] * r.velocity[0] + r.velocity[1] * r.velocity[1] +
                                                    r.velocity[2] * r.velocity[2]));
  const Vec3& g = scene_.gravity;
  const double gravityTerm = std::sqrt(5.0 * grid_.cellSize * std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]));
  // The likely cause: a CFL far below the default, a speed the scene sets, else the flow itself.
  constexpr double kSmallCfl = 0.01;  // 100 times the default's substeps
  std::string fields;
  if (scene_.time.cfl < kSmallCfl) fields = "time.cfl";
  else if (gravityTerm >= std::max(particleSpeed, emitterSpeed)) fields = "gravity, time.cfl";
  else if (emitterSpeed >= 0.5 * particleSpeed) fields = "emitters[].speed, time.cfl";
  else if (initialSpeed >= 0.5 * particleSpeed) fields = "liquid[].velocity, time.cfl";
  else fields = "the flow (its speed grew far beyond the scene's: unstable?), time.cfl";
  char text[400];
  std::snprintf(text, sizeof text,
                "more than %d substeps for the frame ending at %.6g s (at %.6g s the step is %.3g s: fastest particle "
                "%.4g m/s, emitters %.4g m/s, gravity margin %.4g m/s, cfl %g, cell %g m)",
                substepLimit_, until, time_, dt, particleSpeed, emitterSpeed, gravityTerm, scene_.time.cfl,
                grid_.cellSize);
  return SubstepLimitError(text, fields);
}

FrameStats FluidSolver::advanceTo(double until, const SubstepObserver& observer) {
  FrameStats stats;
  while (time_ < until) {
    double dt = std::min(stableTimeStep(), until - time_);
    if (until - time_ - dt < kMinimumSubstepFraction * dt && until - time_ > dt) dt = 0.5 * (until - time_);
    if (stats.substeps >= substepLimit_) throw substepLimitError(until, dt);
    substep(dt, stats, observer);
    time_ = (until - time_ - dt <= 0.0) ? until : time_ + dt;
    ++stats.substeps;
  }
  if (stats.substeps > 0) {
    const auto start = std::chrono::steady_clock::now();
    maintainParticles(stats);
    stats.stageSeconds.particleMaintenance +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  stats.particles = particles_.size();
  stats.liquidVolume = liquidVolume();
  double speed2 = 0.0;
  for (const Vec3f& v : particles_.velocity)
    speed2 = std::max(speed2, static_cast<double>(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  stats.maxSpeed = std::sqrt(speed2);
  return stats;
}

void FluidSolver::placeSolidsAndEmit(double dt, FrameStats& stats) {
  Workspace& w = *work_;
  if (w.solidsMove)
    w.solids = solidBoundaryAt(grid_, scene_.domain, scene_.solids, w.meshWalls, time_ + dt,
                               w.meshes.solids);
  for (std::size_t e = 0; e < scene_.emitters.size(); ++e)
    stats.particlesEmitted +=
        emitParticles(particles_, scene_.emitters[e], w.emitters[e], time_, time_ + dt,
                      EmissionSetting{grid_, w.solids.nodeDistance, scene_.solver.particlesPerCell,
                                      scene_.seed, e});
  assignParticleIds(particles_.id, nextParticleId_);
}

const CellIndex& FluidSolver::particlesToFaces() {
  Workspace& w = *work_;
  const CellIndex& index = sortParticlesByCell(particles_, grid_, w.transfer);
  particlesToGrid(particles_, grid_, scene_.solver.transfer, velocity_, w.weight, w.transfer);
  for (int a = 0; a < 3; ++a) {
    if (w.reached[a].size() != w.weight[a].size()) w.reached[a] = Array3<std::uint8_t>(w.weight[a].size(), 0);
    std::uint8_t* const reached = w.reached[a].data();
    const float* const weight = w.weight[a].data();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, w.weight[a].elementCount()),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t f = r.begin(); f < r.end(); ++f) reached[f] = weight[f] > 0.0f;
                      });
  }
  return index;
}

void FluidSolver::projectPressure(double dt, FrameStats& stats) {
  Workspace& w = *work_;
  PressureSettings settings;
  settings.tolerance = scene_.solver.pressureTolerance;
  settings.maxIterations = scene_.solver.maxPressureIterations;
  // With the level set and static solids, the level runs on through them (liquid_level_set.h);
  // otherwise extendIntoSolids' cut-cell rules (a moving solid's swept cells need them too).
  const Array3f pressurePhi =
      (w.solidsMove || !usesLevelSet())
          ? extendIntoSolids(liquidPhi_, w.solids, upFromGravity(scene_.gravity))
          : extendLevelAcrossSolids(liquidPhi_, w.solids.nodeDistance,
                                    upFromGravity(scene_.gravity), grid_.cellSize);
  const PressureReport report =
      w.pressure.project(velocity_,
                         PressureProblem{pressurePhi, w.solids.faceOpen, w.solids.faceVelocity,
                                         grid_, properties_.density, dt},
                         settings);
  stats.pressureIterations += report.iterations;
  stats.pressureResidual = std::max(stats.pressureResidual, report.relativeResidual);
  stats.pressureConverged = stats.pressureConverged && report.converged;
  requireFiniteFaceVelocities(velocity_, grid_, time_, "pressure projection");
  stats.maxDivergence =
      std::max(stats.maxDivergence,
               maxRelativeDivergence(
                   velocity_, pressurePhi, w.solids.faceOpen, w.solids.faceVelocity, grid_,
                   std::hypot(scene_.gravity[0], scene_.gravity[1], scene_.gravity[2]) * dt));
}

double FluidSolver::substep(double dt, FrameStats& stats, const SubstepObserver& observer) {
  Workspace& w = *work_;
  placeSolidsAndEmit(dt, stats);
  using Clock = std::chrono::steady_clock;
  auto mark = Clock::now();
  const auto lap = [&mark](double& total) {
    const auto now = Clock::now();
    total += std::chrono::duration<double>(now - mark).count();
    mark = now;
  };
  FrameStats::StageSeconds& seconds = stats.stageSeconds;
  // 1. Particles → grid.
  const CellIndex& index = particlesToFaces();
  lap(seconds.transfer);
  extrapolateVelocity(velocity_, w.reached, kExtraLayers);
  const bool flip = scene_.solver.transfer == TransferScheme::Flip;
  if (flip) w.oldVelocity = velocity_;  // APIC does not read it
  // 2. Free surface, held to the particles before gravity changes the velocity it reads.
  liquidPhi_ = surfaceFromParticles(index);
  if (usesLevelSet()) {
    levelSet_.holdToParticles(liquidPhi_, index, velocity_, w.solids.sceneNodeDistance,
                              levelSetHold());
    liquidPhi_ = levelSet_.phi();
  }
  lap(seconds.surface);
  // 3. Body forces, then the pressure projection.
  for (int a = 0; a < 3; ++a) {
    const float dv = static_cast<float>(scene_.gravity[a] * dt);
    for (float& u : velocity_[a].values()) u += dv;
  }
  lap(seconds.forces);
  projectPressure(dt, stats);
  lap(seconds.pressure);
  // 4. Velocity beyond the liquid, grid → particles, advection.
  extrapolateVelocity(velocity_, w.pressure.validFaces(), static_cast<int>(std::ceil(scene_.time.cfl)) + kExtraLayers);
  constrainToSolids(velocity_, w.solids);
  gridToParticles(particles_, velocity_, flip ? w.oldVelocity : velocity_, grid_, scene_.solver);
  lap(seconds.gridToParticles);
  const std::size_t left =
      advectParticles(particles_, velocity_, w.solids, SolidTimes{time_, time_ + dt}, dt);
  stats.particlesDeleted += left;
  leftThroughOpenFaces_ += left;
  if (usesLevelSet())
    levelSet_.advect(velocity_, w.solids.sceneNodeDistance, dt,
                     std::ceil(scene_.time.cfl) + kLevelSetMarginCells);
  lap(seconds.advection);
  if (observer) {
    observer(LiquidState{particles_.position, particles_.velocity, particles_.id, liquidPhi_,
                         velocity_, w.solids.nodeDistance, grid_},
             time_, dt);
    lap(seconds.bubbles);
  }
  return dt;
}

}  // namespace fluidsound::sim
