// The bubble model's surface distance alone (not a test): SurfaceDistance::rebuild on seven
// liquid fields of the glass pour (scenes/glass_pour.scene.json, every 100th substep of its 2 s),
// with the bubble model's bands. A whole run's bubble share moves by ±2 points between runs on a
// shared machine; this isolates the rebuild (the whole-grid passes and the band's nearest points)
// so that a change to it can be measured: the minimum over repetitions is the figure to compare.
//   build/tests/fluidsound_bench --benchmark_filter=SurfaceDistanceRebuild
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/scene_file.h"
#include "io/scene_meshes.h"
#include "sim/bubbles/bubble_model.h"
#include "sim/fluid/fluid_solver.h"
#include "sim/bubbles/liquid_distance.h"

namespace {

using namespace fluidsound;

/// The fields a rebuild reads, saved from one substep.
struct SavedSubstep {
  sim::Array3f phi, solidNodes;
};

struct SavedPour {
  sim::GridGeometry grid;
  double band = 0.0, airBand = 0.0;
  std::vector<SavedSubstep> substeps;
};

/// Runs the glass pour once with the bubble model attached, saving every 100th substep's fields.
const SavedPour& glassPourFields() {
  static const SavedPour saved = [] {
    sim::Scene scene =
        io::readScene(std::string(FLUIDSOUND_SOURCE_DIR) + "/scenes/glass_pour.scene.json");
    io::loadSceneMeshes(scene);
    sim::FluidSolver solver(scene);
    sim::BubbleModel model(scene.bubbles, scene.seed, scene.gravity);
    SavedPour out;
    long substep = 0;
    const sim::SubstepObserver observer = [&](const sim::LiquidState& liquid, double t, double dt) {
      model.step(liquid, t, dt);
      if (++substep % 100 != 0) return;
      out.grid = liquid.grid;
      out.band = model.surfaceDistance().band();
      out.airBand = model.surfaceDistance().airBand();
      out.substeps.push_back({liquid.liquidDistance, liquid.solidNodeDistance});
    };
    const int frames = static_cast<int>(std::lround(scene.time.duration * scene.time.fps));
    for (int f = 1; f <= frames; ++f) solver.advanceTo(f / scene.time.fps, observer);
    return out;
  }();
  return saved;
}

/// One iteration: one rebuild, of the saved fields in turn (one object, as the bubble model keeps).
void BM_SurfaceDistanceRebuild(benchmark::State& state) {
  const SavedPour& pour = glassPourFields();
  sim::SurfaceDistance distance;
  std::size_t next = 0;
  for (auto _ : state) {
    const SavedSubstep& s = pour.substeps[next];
    distance.rebuild(s.phi, s.solidNodes, pour.grid, pour.band, pour.airBand);
    benchmark::DoNotOptimize(distance.field().data());
    next = (next + 1) % pour.substeps.size();
  }
  state.counters["fields"] = static_cast<double>(pour.substeps.size());
  state.counters["band_cells"] = pour.band / pour.grid.cellSize;
  state.counters["air_band_cells"] = pour.airBand / pour.grid.cellSize;
}

// Short repetitions (each field twice, about 5 ms) and many of them: on a shared machine the
// minimum of many short runs is steady where a long run's mean is not.
BENCHMARK(BM_SurfaceDistanceRebuild)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime()
    ->Iterations(14)
    ->Repetitions(200)
    ->ComputeStatistics("min",
                        [](const std::vector<double>& v) {
                          return *std::min_element(v.begin(), v.end());
                        })
    ->ReportAggregatesOnly(true);

}  // namespace
