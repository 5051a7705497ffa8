// Synthesis throughput in oscillator-samples per second (one bubble advanced by one sample = one
// oscillator-sample), for 1 k, 10 k and 100 k bubbles with moving depth and transfer on two
// listeners, and two baselines in the same run: a per-sample sin/exp loop and a plain
// single-thread complex-rotation loop at constant frequency. Run: build/tests/fluidsound_bench
// (or tools/bench.sh, which also prints the ratios).
#include <benchmark/benchmark.h>
#include <oneapi/tbb/info.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include "acoustics/synthesizer.h"

namespace {

using namespace fluidsound::acoustics;

/// `count` bubbles born uniformly over `span` seconds, radii log-uniform in 0.5–4 mm, each rising
/// from 5–40 mm deep to 1.6 R over 0.2 s (7 frames at 30 fps), transfer changing on both channels.
/// Bubbles are listed in order of birth, as the simulation writes them (and as they are built
/// here, so their tracks lie in memory in that order, as after reading a file).
BubbleTrackSet movingBubbles(std::size_t count, double span) {
  BubbleTrackSet set;
  set.listeners = {"left", "right"};
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> birth(0.0, span), logRadius(std::log(0.5e-3), std::log(4e-3)),
      depth(5e-3, 40e-3), pan(0.6, 1.0);
  std::vector<double> births(count);
  for (double& t : births) t = birth(random);
  std::sort(births.begin(), births.end());
  for (std::size_t i = 0; i < count; ++i) {
    BubbleTrack b;
    b.radius = std::exp(logRadius(random));
    b.birth = births[i];
    const double h0 = depth(random), p = pan(random);
    for (int k = 0; k < 7; ++k) {
      const double u = k / 6.0;
      b.track.push_back({b.birth + k / 30.0, h0 + (1.6 * b.radius - h0) * u,
                         {2.4e-3 * p * (1.0 - 0.2 * u), 2.4e-3 * (1.6 - p) * (1.0 - 0.2 * u)}, std::nullopt});
    }
    set.bubbles.push_back(std::move(b));
  }
  return set;
}

void BM_Synthesize(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  const BubbleTrackSet set = movingBubbles(count, 10.0);
  SynthesisSettings settings;
  std::int64_t samples = 0;
  for (auto _ : state) {
    SynthesisResult r = synthesize(set, settings);
    benchmark::DoNotOptimize(r.channels[0].data());
    samples += r.report.oscillatorSamples;
  }
  state.SetItemsProcessed(samples);
  state.counters["threads"] = oneapi::tbb::info::default_concurrency();
  state.counters["bubbles"] = static_cast<double>(count);
}
BENCHMARK(BM_Synthesize)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

constexpr int kBaselineOscillators = 256;
constexpr int kBaselineSamples = 48000;

/// Baseline 1: p = A e^{−βt} sin(ωt) evaluated directly per sample (one thread, double).
void BM_BaselineSinExp(benchmark::State& state) {
  std::vector<double> out(kBaselineSamples);
  for (auto _ : state) {
    for (int k = 0; k < kBaselineOscillators; ++k) {
      const double w = 2 * std::numbers::pi * (500.0 + 10.0 * k), beta = 50.0 + k;
      for (int n = 0; n < kBaselineSamples; ++n) {
        const double t = n / 48000.0;
        out[n] += std::exp(-beta * t) * std::sin(w * t);
      }
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * kBaselineOscillators * kBaselineSamples);
  state.counters["threads"] = 1;
}
BENCHMARK(BM_BaselineSinExp)->Unit(benchmark::kMillisecond);

/// Baseline 2: a plain complex rotation z ← z·r per sample at constant frequency (one thread,
/// float, oscillator by oscillator).
void BM_BaselineComplexRotation(benchmark::State& state) {
  std::vector<float> out(kBaselineSamples);
  for (auto _ : state) {
    for (int k = 0; k < kBaselineOscillators; ++k) {
      const double w = 2 * std::numbers::pi * (500.0 + 10.0 * k), beta = 50.0 + k;
      const std::complex<double> r = std::polar(std::exp(-beta / 48000.0), w / 48000.0);
      const auto rr = static_cast<float>(r.real()), ri = static_cast<float>(r.imag());
      float zr = 0.0f, zi = 1.0f;
      for (int n = 0; n < kBaselineSamples; ++n) {
        out[n] += zi;
        // Written out rather than std::complex<float>::operator*=, whose NaN checks (C Annex G)
        // would make the baseline needlessly slow.
        const float nr = zr * rr - zi * ri;
        zi = zr * ri + zi * rr;
        zr = nr;
      }
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * kBaselineOscillators * kBaselineSamples);
  state.counters["threads"] = 1;
}
BENCHMARK(BM_BaselineComplexRotation)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
