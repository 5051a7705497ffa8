// sim/fluid/fluid_solver.h — the liquid solver: APIC/FLIP particles on a MAC grid, ghost-fluid free
// surface, variational solid walls (Batty, Bertails & Bridson 2007), CFL-limited substeps.
// The step reads as the algorithm (Batty's Fluid3D `advance`): transfer, forces, project,
// extrapolate, transfer back, advect.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/liquid_level_set.h"
#include "sim/fluid/liquid_state.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particles.h"
#include "sim/fluid/fluid_scene.h"

namespace fluidsound::sim {

struct CellIndex;  // particle_transfer.h

/// What one frame of simulation did, for the progress line and report.json.
struct FrameStats {
  int substeps = 0;
  int pressureIterations = 0;       ///< summed over substeps
  double pressureResidual = 0.0;    ///< worst relative residual of the frame's solves
  bool pressureConverged = true;
  std::size_t particles = 0;
  std::size_t particlesDeleted = 0; ///< left through open faces
  std::size_t particlesEmitted = 0; ///< added by the scene's emitters
  std::size_t particlesReseeded = 0; ///< added to liquid cells holding fewer than 4 (once per frame)
  std::size_t particlesThinned = 0;  ///< removed from cells holding more than 16
  int densityIterations = 0;        ///< CG iterations of the density correction (once per frame)
  double maxDensityExcess = 0.0;    ///< largest ρ/ρ₀ − ρ_expected it found [-]
  double liquidVolume = 0.0;        ///< [m³], from the surface at the frame's end, outside the solids
  double maxDivergence = 0.0;       ///< worst max|∇·u|·h/|u|max after a projection
  double maxSpeed = 0.0;            ///< fastest particle at the frame's end [m/s]
  /// Wall time per stage [s], summed over the frame's substeps: sort + particle→grid, forces and
  /// extrapolation, liquid surface, pressure, grid→particle, advection.
  struct StageSeconds {
    double transfer = 0.0, forces = 0.0, surface = 0.0, pressure = 0.0, gridToParticles = 0.0, advection = 0.0;
    double particleMaintenance = 0.0;  ///< once per frame: density correction and reseeding
    double bubbles = 0.0;              ///< the substep observer (the bubble model), if any
    /// The substeps' solver stages (all but particleMaintenance and bubbles).
    double substepTotal() const { return transfer + forces + surface + pressure + gridToParticles + advection; }
    StageSeconds& operator+=(const StageSeconds& o) {
      transfer += o.transfer, forces += o.forces, surface += o.surface, pressure += o.pressure;
      gridToParticles += o.gridToParticles, advection += o.advection, particleMaintenance += o.particleMaintenance;
      bubbles += o.bubbles;
      return *this;
    }
  } stageSeconds;
};

/// Liquid properties the solver needs.
struct FluidProperties {
  double density = 998.0;  ///< ρ [kg/m³], water at 20 °C
};

/// @brief A frame needed more than its substep limit. what() is one line with the time step and
///        the speeds that set it; likelyFields() names the scene fields to look at.
class SubstepLimitError : public std::runtime_error {
 public:
  SubstepLimitError(const std::string& message, std::string likelyFields)
      : std::runtime_error(message), likelyFields_(std::move(likelyFields)) {}
  const std::string& likelyFields() const { return likelyFields_; }

 private:
  std::string likelyFields_;
};

/// Called at the end of every substep with the liquid after it (views, valid during the call),
/// the substep's start time t [s] and length dt [s]: the bubble model's hook.
using SubstepObserver = std::function<void(const LiquidState& liquid, double t, double dt)>;

class FluidSolver {
 public:
  /// @brief Sets up the grid, the mesh distances on it (sim/fluid/scene_mesh_distances.h), the
  ///        solids and the initial particles of a validated scene.
  /// @throws std::invalid_argument for a mesh whose triangles were not read (io::loadSceneMeshes)
  explicit FluidSolver(const FluidScene& scene, FluidProperties properties = {});
  ~FluidSolver();
  FluidSolver(const FluidSolver&) = delete;
  FluidSolver& operator=(const FluidSolver&) = delete;

  /// @brief Advances to time `until` [s] in CFL-limited substeps, calling `observer` (if any)
  ///        after each, then corrects and reseeds the particles once (call once per frame).
  /// @throws SubstepLimitError before a substep beyond the limit (kMaxSubstepsPerFrame unless
  ///         limitSubstepsPerFrame set another)
  /// @throws SimulationFailure (sim/fluid/simulation_failure.h) when a particle or face velocity is not
  ///         finite or the time step no longer advances the clock: the solver blew up
  FrameStats advanceTo(double until, const SubstepObserver& observer = {});
  /// @brief The substep limit of advanceTo, > 0 (tests set a small one to reach it quickly).
  void limitSubstepsPerFrame(int limit) { substepLimit_ = limit; }

  double time() const { return time_; }
  /// @brief Appends keys to the path of the scene's solid `solid` (a body the rigid-body stage
  ///        moves frame by frame: sim::simulate). The solid must have had a path from the start
  ///        (so the solver treats the solids as moving), and the keys must come after its last.
  /// @throws std::invalid_argument otherwise
  void extendSolidPath(std::size_t solid, std::span<const PathKey> keys);
  const GridGeometry& grid() const { return grid_; }
  const Particles& particles() const { return particles_; }
  /// Face velocity after the last substep [m/s].
  const MacVelocity& velocity() const { return velocity_; }
  /// Liquid signed distance at cell centres [m] (negative inside), after the last substep.
  const Array3f& liquidDistance() const { return liquidPhi_; }
  /// @brief The liquid's volume [m³] the surface after the last substep (or the initial one)
  ///        describes, counted outside the scene solids: FrameStats::liquidVolume of every frame.
  double liquidVolume() const;
  /// Particle radius used for the surface [m].
  double particleRadius() const { return particleRadius_; }

 private:
  struct Workspace;
  double substep(double dt, FrameStats& stats, const SubstepObserver& observer);
  /// A substep's start: the solids placed at its end (when they move), the emitters' particles.
  void placeSolidsAndEmit(double dt, FrameStats& stats);
  /// Sorts the particles and transfers them to the faces (velocity_, the reached faces).
  const CellIndex& particlesToFaces();
  /// Makes velocity_ divergence-free in the liquid; the solve's figures into `stats`.
  void projectPressure(double dt, FrameStats& stats);
  double stableTimeStep() const;
  /// The SubstepLimitError for a frame ending at `until` whose next step is `dt` [s].
  SubstepLimitError substepLimitError(double until, double dt) const;
  /// The liquid distance at cell centres from the sorted particles.
  Array3f surfaceFromParticles(const CellIndex& index) const;
  LevelSetHold levelSetHold() const;
  bool usesLevelSet() const;  ///< scene.solver.surface is LevelSet
  /// Particles per cell that count as a full cell (half the seeding count, rounded up): the
  /// surface kernel's interior shortcut and the level set's certain-liquid rule.
  std::size_t fullCellCount() const;
  /// Once per frame: the density correction, then reseeding (docs/solver.md, steps 10–11).
  void maintainParticles(FrameStats& stats);

  FluidScene scene_;
  FluidProperties properties_;
  GridGeometry grid_;
  double time_ = 0.0;
  int substepLimit_ = kMaxSubstepsPerFrame;
  double particleRadius_ = 0.0;
  std::uint64_t reseedPasses_ = 0;
  std::uint64_t nextParticleId_ = 0;  ///< the id the next new particle gets (particle_ids.h)
  Particles particles_;
  MacVelocity velocity_;
  Array3f liquidPhi_;
  LiquidLevelSet levelSet_;
  /// The liquid's volume [m³]: the level set's at the start, then changed only by what the
  /// emitters add and what leaves through open faces (h³/particlesPerCell per particle).
  double liquidVolumeTarget_ = 0.0;
  std::size_t leftThroughOpenFaces_ = 0;  ///< particles advection deleted since the last frame
  std::unique_ptr<Workspace> work_;
};

}  // namespace fluidsound::sim
