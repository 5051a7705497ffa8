// sim/simulation.cpp — the simulate stage's frame loop (see simulation.h).
#include "sim/simulation.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/bubbles/bubble_model.h"
#include "sim/fluid/simulation_failure.h"

namespace fluidsound::sim {

int lastSceneFrame(const Scene& scene) {
  return static_cast<int>(std::lround(scene.time.duration * scene.time.fps));
}

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Thrown from the substep hook when the observer asks to stop; caught by simulate.
struct StopRequested {};

/// The solver and bubble model of one run, and the frame being made.
class FrameLoop {
 public:
  FrameLoop(const Scene& scene, SimulationObserver& observer)
      : scene_(scene),
        observer_(observer),
        bodies_(scene.bodies.empty() ? std::nullopt : std::optional<BodyStepper>(std::in_place, scene)),
        solver_(bodies_ ? sceneWithBodiesAsSolids(scene, bodies_->motion()) : scene),
        bubbles_(scene.bubbles, scene.seed, scene.gravity),
        reach_(largestBodyRadius(scene) + scene.domain.cell) {}

  /// Makes frame f (frame 0: the initial state, whose volume is the reference) and records it.
  FrameRecord make(int f, double& bubbleSeconds);
  FrameView view(bool kept) const {
    return {kept, solver_.grid(), solver_.particles(), solver_.velocity(),
            solver_.particleRadius()};
  }
  const BubbleModel& bubbles() const { return bubbles_; }
  const FluidSolver& solver() const { return solver_; }
  std::optional<BodyMotion> bodyMotion() const {
    return bodies_ ? std::optional<BodyMotion>(bodies_->motion()) : std::nullopt;
  }

 private:
  /// The bodies stepped to `time` in the liquid the solver holds now, their paths handed to it.
  void moveBodies(double time);

  const Scene& scene_;
  SimulationObserver& observer_;
  std::optional<BodyStepper> bodies_;  // before solver_: its scene holds the bodies as solids
  FluidSolver solver_;
  BubbleModel bubbles_;  // runs inside the loop on the in-memory state (DESIGN.md)
  double reach_;         // [m] how far across the bodies liquidAround looks
};

void FrameLoop::moveBodies(double time) {
  if (!bodies_) return;
  // A scene with no liquid and no emitter never holds any: no test.
  const LiquidRegionTest around = scene_.liquid.empty() && scene_.emitters.empty()
                                      ? LiquidRegionTest{}
                                      : liquidAround(solver_.liquidDistance(), solver_.grid(), scene_.gravity, reach_);
  const std::vector<std::vector<PathKey>> keys = bodies_->advanceTo(time, around);
  for (std::size_t b = 0; b < keys.size(); ++b)
    if (!scene_.bodies[b].isStatic && !keys[b].empty()) solver_.extendSolidPath(scene_.solids.size() + b, keys[b]);
}

FrameRecord FrameLoop::make(int f, double& bubbleSeconds) {
  const auto t0 = Clock::now();
  FrameStats stats;
  if (f == 0) {  // nothing simulated, but its volume is the reference
    stats.particles = solver_.particles().size();
    stats.liquidVolume = solver_.liquidVolume();  // outside the solids, as every later frame's
  } else {
    const SubstepObserver stepBubbles = [this](const LiquidState& liquid, double t, double dt) {
      if (observer_.wasInterrupted()) throw StopRequested{};
      bubbles_.step(liquid, t, dt);
    };
    try {
      moveBodies(f / scene_.time.fps);
      stats = solver_.advanceTo(f / scene_.time.fps, stepBubbles);
    } catch (const SubstepLimitError& e) {
      throw SubstepLimitError("frame " + std::to_string(f) + " needs " + e.what(),
                              e.likelyFields());
    } catch (const SimulationFailure& e) {
      throw SimulationFailure("frame " + std::to_string(f) + ": " + e.what());
    }
    const auto s0 = Clock::now();
    bubbles_.sampleFrame(solver_.time());  // the bubble model's time too, not the fluid's
    bubbleSeconds += stats.stageSeconds.bubbles + secondsSince(s0);
  }
  FrameRecord record;
  record.frame = f;
  record.time = solver_.time();
  record.fluid = stats;
  record.particles = solver_.particles().size();
  record.bubblesAlive = bubbles_.aliveCount();
  record.bubblesTotal = bubbles_.bubbles().size();
  record.simulationSeconds = secondsSince(t0);
  return record;
}

}  // namespace

SimulationResult simulate(const Scene& scene, const SimulationOptions& options,
                          SimulationObserver& observer) {
  const int last = options.lastFrame.value_or(lastSceneFrame(scene));
  if (options.firstFrame < 0 || last < options.firstFrame || last > lastSceneFrame(scene))
    throw std::invalid_argument("simulate: frames " + std::to_string(options.firstFrame) + " to " +
                                std::to_string(last) + " are not within 0 to " +
                                std::to_string(lastSceneFrame(scene)));
  FrameLoop loop(scene, observer);
  SimulationResult result;
  double loopSeconds = 0.0;
  observer.started(last + 1);
  for (int f = 0; f <= last; ++f) {
    if (observer.wasInterrupted()) {
      result.interrupted = SimulationStop{f, false};
      break;
    }
    FrameRecord record;
    try {
      record = loop.make(f, result.bubbleSeconds);
    } catch (const StopRequested&) {
      result.interrupted = SimulationStop{f, true};
      break;
    }
    const auto w0 = Clock::now();
    observer.onFrame(loop.view(f >= options.firstFrame), record);
    record.observerSeconds = secondsSince(w0);
    loopSeconds += record.simulationSeconds;
    result.observerSeconds += record.observerSeconds;
    result.frames.push_back(record);
    observer.progress(static_cast<double>(f + 1) / (last + 1));
  }
  result.simulationSeconds = loopSeconds - result.bubbleSeconds;
  result.bubbles = loop.bubbles().bubbles();
  result.bodies = loop.bodyMotion();
  result.grid = loop.solver().grid();
  return result;
}

}  // namespace fluidsound::sim
