// The solids' costs (issue 22; docs/solids.md, Speed): modal analysis of steel bodies of about
// 10 k and 50 k degrees of freedom — a thin plate (many audible modes: 200 asked for) and a compact
// block (the densest factorisation) — in seconds and peak memory, and the synthesis of 1 000 modes
// struck by 1 000 impacts over 10 s in oscillator-samples per second (one mode advanced by one
// sample), beside the bubble synthesizer's BM_Synthesize in the same run. Peak memory is the
// process's (getrusage), so run one size per process for its own figure:
//   build/tests/fluidsound_bench --benchmark_filter='BM_ModalAnalysis.*/10'   (then .../50)
//   build/tests/fluidsound_bench --benchmark_filter='BM_ModalImpacts|BM_Synthesize/1000$'
//   build/tests/fluidsound_bench --benchmark_filter=BM_GlassCompression   (about 2 min)
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <vector>

#include "acoustics/modal/modal_analysis.h"
#include "acoustics/modal/modal_synthesis.h"
#include "acoustics/modal/mode_compression.h"
#include "acoustics/modal/contact_impacts.h"
#include "tests/support/third_octave.h"

namespace {

using namespace fluidsound::acoustics;

double peakResidentMebibytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

/// A steel plate of 5 mm voxels, one thick: n × n cells (2·(n+1)² nodes, 6(n+1)² unknowns).
VoxelSolid plate(int n) { return voxelBox({0.005 * n, 0.005 * n, 0.005}, 0.005); }
/// A steel block of 1 cm voxels, n × n × n cells (3(n+1)³ unknowns).
VoxelSolid block(int n) { return voxelBox({0.01 * n, 0.01 * n, 0.01 * n}, 0.01); }

void analyse(benchmark::State& state, const VoxelSolid& solid) {
  ModalSettings settings;  // 200 modes up to 20 kHz, the defaults
  ModalModel model;
  for (auto _ : state) {
    model = analyseModes(solid, *findSolidMaterial("steel"), settings);
    benchmark::DoNotOptimize(model.frequency.data());
  }
  state.counters["dof"] = model.dofCount;
  state.counters["modes"] = static_cast<double>(model.frequency.size());
  state.counters["lanczos_solves"] = model.operations;
  state.counters["peak_rss_MiB"] = peakResidentMebibytes();
}

/// Argument: thousands of unknowns (10 or 50).
void BM_ModalAnalysisPlate(benchmark::State& state) { analyse(state, plate(state.range(0) == 10 ? 40 : 90)); }
void BM_ModalAnalysisBlock(benchmark::State& state) { analyse(state, block(state.range(0) == 10 ? 14 : 25)); }
BENCHMARK(BM_ModalAnalysisPlate)->Arg(10)->Arg(50)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_ModalAnalysisBlock)->Arg(10)->Arg(50)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

/// 1 000 modes log-spaced over 50 Hz – 18 kHz with steel's Rayleigh decay, shapes random at one
/// surface node; 1 000 impacts at random times over 10 s, a 48 kHz render of 10 s.
void BM_ModalImpacts(benchmark::State& state) {
  constexpr std::size_t kModes = 1000, kImpacts = 1000, kSamples = 480000;
  const fluidsound::SolidMaterial steel = *findSolidMaterial("steel");
  ModalModel model;
  std::mt19937_64 random(7);
  std::normal_distribution<double> shape(0.0, 1.0);
  std::uniform_real_distribution<double> when(0.0, 10.0);
  model.surfaceNodes = {0};
  model.surfacePositions = {Eigen::Vector3d::Zero()};
  model.surfaceShapes.resize(3, kModes);
  for (std::size_t j = 0; j < kModes; ++j) {
    const double f = 50.0 * std::pow(18000.0 / 50.0, static_cast<double>(j) / (kModes - 1));
    const double omega = 2.0 * std::numbers::pi * f, d = modalDecayRate(steel, omega);
    model.frequency.push_back(f);
    model.decayRate.push_back(d);
    model.dampedFrequency.push_back(std::sqrt(omega * omega - d * d) / (2.0 * std::numbers::pi));
    for (int c = 0; c < 3; ++c) model.surfaceShapes(c, static_cast<Eigen::Index>(j)) = static_cast<float>(shape(random));
  }
  std::vector<ModalImpact> impacts;
  for (std::size_t e = 0; e < kImpacts; ++e) impacts.push_back({when(random), 0, {0.0, 1e-3, 0.0}, 50e-6});
  const std::vector<std::complex<double>> gains(kModes, 1.0);
  ModalSynthesisSettings settings;
  settings.truncation = static_cast<double>(state.range(0)) == 0 ? 0.0 : 1e-5;
  const ModeGroups groups = groupIndistinguishableModes(model.frequency);
  if (state.range(1) == 1) settings.compression = &groups;
  std::int64_t samples = 0;
  for (auto _ : state) {
    ModalSynthesisStatistics statistics;
    const std::vector<float> out = synthesizeModalImpacts(model, impacts, gains, kSamples, 0.0, settings, &statistics);
    benchmark::DoNotOptimize(out.data());
    samples += static_cast<std::int64_t>(statistics.oscillatorSamples);
  }
  state.SetItemsProcessed(samples);
  state.counters["oscillators"] = static_cast<double>(settings.compression ? groups.first.size() : kModes);
  state.counters["threads"] = 1;
}
BENCHMARK(BM_ModalImpacts)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->ArgNames({"truncation", "compression"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

/// The drinking glass of scenes/meshes/glass.obj as the cylinder it approximates (inner radius
/// 30 mm, wall 2 mm, 100 mm high, base 4 mm) in 1.25 mm voxels, the finest resolution at which
/// its wall holds a voxel all round: its modes up to 20 kHz, then one strike on its rim rendered
/// over 1 s with every mode and with the modes the ear cannot tell apart merged (T8), compared
/// band by band in third octaves where the full render holds sound (within 60 dB of its loudest).
void BM_GlassCompression(benchmark::State& state) {
  const auto inside = [](const Eigen::Vector3d& x) {
    const double r = std::hypot(x.x(), x.z());
    return r < 0.032 && x.y() > 0.0 && x.y() < 0.1 && !(r < 0.030 && x.y() > 0.004);
  };
  const VoxelSolid glass = voxelSolidFromInside(inside, {-0.032, 0.0, -0.032}, {0.032, 0.1, 0.032}, 0.00125);
  ModalModel model;
  for (auto _ : state) model = analyseModes(glass, *findSolidMaterial("glass"), ModalSettings{});
  const ModeGroups groups = groupIndistinguishableModes(model.frequency);
  const ModalImpact strike{0.0, nearestSurfaceNode(model, {0.032, 0.095, 0.0}), {-0.05, 0.0, 0.0}, 50e-6};
  const std::vector<std::complex<double>> gains(model.frequency.size(), 1.0);
  ModalSynthesisStatistics full{}, merged{};
  ModalSynthesisSettings every{48000.0, 0.0}, fewer{48000.0, 0.0};
  fewer.compression = &groups;
  const auto a = synthesizeModalImpacts(model, {&strike, 1}, gains, 48000, 0.0, every, &full);
  const auto b = synthesizeModalImpacts(model, {&strike, 1}, gains, 48000, 0.0, fewer, &merged);
  const std::vector<double> x = fluidsound::test::thirdOctaveLevels(a, 48000.0);
  const std::vector<double> y = fluidsound::test::thirdOctaveLevels(b, 48000.0);
  const double loudest = *std::max_element(x.begin(), x.end());
  double worst = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (x[k] > loudest - 60.0) worst = std::max(worst, std::abs(y[k] - x[k]));
  double furthest = 0.0;  // a merged mode's distance from its kept one, in discrimination limits
  for (std::size_t j = 0; j < model.frequency.size(); ++j) {
    const double kept = model.frequency[groups.first[groups.group[j]]];
    furthest = std::max(furthest, std::abs(model.frequency[j] - kept) / frequencyDiscriminationLimit(kept));
  }
  state.counters["dof"] = model.dofCount;
  state.counters["modes"] = static_cast<double>(model.frequency.size());
  state.counters["oscillators"] = static_cast<double>(groups.first.size());
  state.counters["worst_band_dB"] = worst;
  state.counters["furthest_merge_limits"] = furthest;
  state.counters["cost_ratio"] = static_cast<double>(merged.oscillatorSamples) / static_cast<double>(full.oscillatorSamples);
}
BENCHMARK(BM_GlassCompression)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
