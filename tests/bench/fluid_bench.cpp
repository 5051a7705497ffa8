// Liquid-solver speed (not a test): a dam break (column a × 2a at the −x wall, n² = 2) at 64³ and
// 128³ cells, one 30-fps frame after a short settling, reporting seconds per frame and per
// substep, CG iterations, particles per second and the split by stage.
//   build/tests/fluidsound_bench --benchmark_filter=DamBreak
#include <benchmark/benchmark.h>
#include <oneapi/tbb/info.h>

#include "sim/fluid/fluid_solver.h"

namespace {

using namespace fluidsound::sim;

FluidScene damBreak(int cells) {
  FluidScene s;
  s.domain.max = {1.0, 1.0, 1.0};
  s.domain.cell = 1.0 / cells;
  s.time.duration = 1.0;
  s.liquid.push_back({Box{{0, 0, 0}, {0.25, 0.5, 1.0}}, {}});
  return s;
}

void BM_DamBreakFrame(benchmark::State& state) {
  const int cells = static_cast<int>(state.range(0));
  FluidSolver solver(damBreak(cells));
  solver.advanceTo(1.0 / 30.0);  // the first frame: the column starts to fall
  FrameStats total;
  int frames = 0;
  double substeps = 0, iterations = 0, particleSteps = 0;
  for (auto _ : state) {
    const FrameStats f = solver.advanceTo(solver.time() + 1.0 / 30.0);
    ++frames;
    substeps += f.substeps;
    iterations += f.pressureIterations;
    particleSteps += static_cast<double>(f.particles) * f.substeps;
    total.stageSeconds += f.stageSeconds;
  }
  const auto& t = total.stageSeconds;
  const double stages = t.substepTotal() + t.particleMaintenance;
  state.counters["particles"] = static_cast<double>(solver.particles().size());
  state.counters["substeps/frame"] = substeps / frames;
  state.counters["cg_iter/substep"] = iterations / substeps;
  state.counters["s/substep"] = t.substepTotal() / substeps;
  state.counters["particles/s"] = benchmark::Counter(particleSteps, benchmark::Counter::kIsRate);
  state.counters["%transfer"] = 100 * t.transfer / stages;
  state.counters["%forces"] = 100 * t.forces / stages;
  state.counters["%surface"] = 100 * t.surface / stages;
  state.counters["%pressure"] = 100 * t.pressure / stages;
  state.counters["%g2p"] = 100 * t.gridToParticles / stages;
  state.counters["%advect"] = 100 * t.advection / stages;
  state.counters["%maintain"] = 100 * t.particleMaintenance / stages;  // density correction, reseeding
  state.counters["threads"] = oneapi::tbb::info::default_concurrency();
}
BENCHMARK(BM_DamBreakFrame)->Arg(64)->Arg(128)->Unit(benchmark::kSecond)->Iterations(2)->UseRealTime();

}  // namespace
