// sim/simulation.h — the simulate stage as one call: the liquid solver frame by frame with the
// bubble model on every substep (DESIGN.md), handing each frame to an observer as it is made and
// returning the bubble histories and the per-frame statistics. Writes and prints nothing: the
// observer does (tools/simulate_command.cpp writes frames/NNNN.vdb, logs and shows progress).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "sim/body_motion.h"
#include "sim/bubbles/bubble_history.h"
#include "sim/core/stage_observer.h"
#include "sim/fluid/fluid_solver.h"
#include "sim/scene.h"

namespace fluidsound::sim {

/// @return the scene's last frame, round(duration · fps): frames 0 … it make the whole scene
int lastSceneFrame(const Scene& scene);

/// What `simulate` makes.
struct SimulationOptions {
  int firstFrame = 0;  ///< the first frame the observer is asked to keep (FrameView::kept)
  std::optional<int> lastFrame;  ///< the last frame simulated; default lastSceneFrame(scene)
};

/// The state at the end of one frame (views into the solver, valid during onFrame only).
struct FrameView {
  bool kept = false;  ///< frame ≥ SimulationOptions::firstFrame: the frames the caller writes
  const GridGeometry& grid;
  const Particles& particles;
  const MacVelocity& velocity;  ///< face velocity after the frame's last substep [m/s]
  double particleRadius = 0.0;  ///< [m], the surface's
};

/// One frame's record: what report.json's `results.frames[]` says of it (docs/cli.md).
struct FrameRecord {
  int frame = 0;
  double time = 0.0;  ///< the solver's time at the frame's end [s]
  FrameStats fluid;   ///< the solver's (frame 0: particles and liquid volume only)
  std::size_t particles = 0;
  std::size_t bubblesAlive = 0, bubblesTotal = 0;
  double simulationSeconds = 0.0;  ///< wall time of the solver and bubble model for the frame [s]
  double observerSeconds = 0.0;    ///< wall time of the observer's onFrame for it [s]
};

/// @brief How a caller follows and stops `simulate` (OpenVDB's interrupter pattern): the stage
///        observer's calls (started with the frame count, progress after each frame's onFrame
///        with the share done in (0, 1], wasInterrupted before every frame and every substep:
///        true stops the simulation there, the frame being made is dropped and the result says
///        where), plus every frame as it is made.
class SimulationObserver : public StageObserver {
 public:
  /// Called after every frame 0 … lastFrame, in order. May throw: simulate then stops with it.
  virtual void onFrame(const FrameView& /*state*/, const FrameRecord& /*record*/) {}
};

/// Where an interrupted simulation stopped.
struct SimulationStop {
  int frame = 0;           ///< the frame being made (not in SimulationResult::frames)
  bool inSubstep = false;  ///< true: during its substeps; false: before it started
};

struct SimulationResult {
  std::vector<BubbleHistory> bubbles;  ///< every bubble made, in creation order
  std::vector<FrameRecord> frames;     ///< the frames made, 0 … the last (or up to the stop)
  std::optional<SimulationStop> interrupted;
  GridGeometry grid;  ///< the solver's grid
  /// The scene's bodies as Bullet moved them frame by frame beside the liquid (none without
  /// bodies): the contact log up to the last frame made, each body's path (sim/body_motion.h).
  std::optional<BodyMotion> bodies;
  /// Wall time [s]: the solver (and frame 0's volume) without the bubble model; the bubble model
  /// (its substep steps and frame samples); the observer's onFrame calls.
  double simulationSeconds = 0.0, bubbleSeconds = 0.0, observerSeconds = 0.0;
};

/// @brief Simulates frames 0 … options.lastFrame of a validated scene whose meshes are loaded
///        (io::loadSceneMeshes): frame 0 is the initial state, frame f ends at f / fps. A scene's
///        bodies are stepped to each frame's end before the liquid, pushed by the liquid around
///        them as the frame before left it (liquidAround), and the liquid sees each as a solid on
///        the path that gives it (sim/body_motion.h).
///        Deterministic: the same scene gives the same bits for any thread count.
/// @throws std::invalid_argument for a frame range outside 0 ≤ first ≤ last ≤ lastSceneFrame
/// @throws SubstepLimitError as FluidSolver::advanceTo, its message prefixed "frame F needs "
/// @throws SimulationFailure as FluidSolver::advanceTo, its message prefixed "frame F: "
SimulationResult simulate(const Scene& scene, const SimulationOptions& options,
                          SimulationObserver& observer);

}  // namespace fluidsound::sim
