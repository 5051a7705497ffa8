// The bubble model's cost against the liquid solver's (not a test): the whole of
// scenes/glass_pour.scene.json (the scene), scenes/dam_break.scene.json,
// scenes/pour_tank.scene.json and scenes/still_basin.scene.json (still water under a flat level:
// every surface point at one distance, which once made the distance's propagation quadratic) with
// the bubble model attached as `fluidsound simulate` runs it, reporting the fluid stage's seconds
// (the solver's substeps and once-per-frame particle maintenance), the bubble model's seconds and
// its share of the fluid stage (issue 6: bubble model and transfer together under 10 %; the
// transfer stage is timed by `fluidsound run`, in its report.json's run.stages.transfer).
//   build/tests/fluidsound_bench --benchmark_filter=BubbleShare
#include <benchmark/benchmark.h>
#include <oneapi/tbb/info.h>

#include <string>

#include "io/scene_file.h"
#include "io/scene_meshes.h"
#include "sim/simulation.h"

namespace {

using namespace fluidsound;

/// Simulates the scene's whole duration as `fluidsound simulate` does (sim::simulate).
void BM_BubbleShare(benchmark::State& state, const std::string& sceneName) {
  sim::Scene scene = io::readScene(std::string(FLUIDSOUND_SOURCE_DIR) + "/scenes/" + sceneName + ".scene.json");
  io::loadSceneMeshes(scene);
  double fluid = 0.0, bubbles = 0.0, substeps = 0.0, made = 0.0;
  for (auto _ : state) {
    sim::SimulationObserver unobserved;
    const sim::SimulationResult result = sim::simulate(scene, {}, unobserved);
    for (const sim::FrameRecord& frame : result.frames) {
      fluid += frame.fluid.stageSeconds.substepTotal() + frame.fluid.stageSeconds.particleMaintenance;
      substeps += frame.fluid.substeps;
    }
    bubbles += result.bubbleSeconds;
    made += static_cast<double>(result.bubbles.size());
  }
  const double runs = static_cast<double>(state.iterations());
  state.counters["fluid_s"] = fluid / runs;
  state.counters["bubbles_s"] = bubbles / runs;
  state.counters["bubble_share_%"] = 100.0 * bubbles / fluid;
  state.counters["bubble_ms/substep"] = 1e3 * bubbles / substeps;
  state.counters["bubbles"] = made / runs;
  state.counters["threads"] = oneapi::tbb::info::default_concurrency();
}

BENCHMARK_CAPTURE(BM_BubbleShare, glass_pour, std::string("glass_pour"))->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK_CAPTURE(BM_BubbleShare, dam_break, std::string("dam_break"))->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK_CAPTURE(BM_BubbleShare, pour_tank, std::string("pour_tank"))->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK_CAPTURE(BM_BubbleShare, still_basin, std::string("still_basin"))->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
