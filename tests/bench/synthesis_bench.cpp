// Synthesis throughput in oscillator-samples per second (one bubble advanced by one sample = one
// oscillator-sample), for 1 k, 10 k and 100 k bubbles with moving depth and transfer on two
// listeners, and two baselines in the same run: a per-sample sin/exp loop and a plain
// single-thread complex-rotation loop at constant frequency. Each synthesis figure is labelled
// with the oscillator kernel that ran (oscillator_kernel.h): BM_Synthesize runs the one the
// synthesizer picks on this CPU, BM_SynthesizeWithKernel each one the CPU can run. Their items/s
// are per second of real time; their CPU time is that of all threads, so items ÷ CPU time is the
// throughput per busy core, a figure that holds on a shared machine. Run:
// build/tests/fluidsound_bench (or tools/bench.sh, which also prints the ratios).
#include <benchmark/benchmark.h>
#include <oneapi/tbb/info.h>
#include <xmmintrin.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "acoustics/synthesis/oscillator_kernel.h"
#include "acoustics/synthesis/synthesizer.h"

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

void synthesizeMovingBubbles(benchmark::State& state, std::optional<OscillatorKernel> kernel) {
  const auto count = static_cast<std::size_t>(state.range(0));
  const BubbleTrackSet set = movingBubbles(count, 10.0);
  SynthesisSettings settings;
  settings.kernel = kernel;
  std::int64_t samples = 0;
  OscillatorKernel ran = OscillatorKernel::baseline;
  for (auto _ : state) {
    SynthesisResult r = synthesize(set, settings);
    benchmark::DoNotOptimize(r.channels[0].data());
    samples += r.report.oscillatorSamples;
    ran = r.report.kernel;
  }
  state.SetItemsProcessed(samples);  // per second of real time: what a user waits
  state.SetLabel(std::string(oscillatorKernelName(ran)));
  state.counters["threads"] = oneapi::tbb::info::default_concurrency();
  state.counters["bubbles"] = static_cast<double>(count);
}

/// The kernel the synthesizer picks on this CPU (the label says which).
void BM_Synthesize(benchmark::State& state) { synthesizeMovingBubbles(state, std::nullopt); }
BENCHMARK(BM_Synthesize)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

/// Each kernel by its index in kOscillatorKernels (0 baseline, 1 AVX2, 2 AVX-512), for a figure of
/// a narrower kernel on a wider CPU; skipped where the CPU cannot run it.
void BM_SynthesizeWithKernel(benchmark::State& state) {
  const OscillatorKernel kernel = kOscillatorKernels[state.range(1)];
  if (!cpuRunsOscillatorKernel(kernel)) {
    state.SkipWithError(
        ("this CPU cannot run " + std::string(oscillatorKernelName(kernel))).c_str());
    return;
  }
  synthesizeMovingBubbles(state, kernel);
}
BENCHMARK(BM_SynthesizeWithKernel)
    ->ArgsProduct({{1000, 10000, 100000}, {0, 1, 2}})
    ->ArgNames({"bubbles", "kernel"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

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

/// Flush-to-zero and denormals-are-zero on this thread while it lives (the SSE control register).
class FlushSubnormalsToZero {
 public:
  FlushSubnormalsToZero() : saved_(_mm_getcsr()) {
    _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero);
  }
  ~FlushSubnormalsToZero() { _mm_setcsr(saved_); }
  FlushSubnormalsToZero(const FlushSubnormalsToZero&) = delete;
  FlushSubnormalsToZero& operator=(const FlushSubnormalsToZero&) = delete;

 private:
  static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;
  unsigned saved_;
};

/// Baseline 2: a plain complex rotation z ← z·r per sample at constant frequency (one thread,
/// float, oscillator by oscillator). Run with subnormals flushed to zero: these decays (β up to
/// 305 /s over 1 s) fall below float's smallest normal number after 87/β s, where Intel CPUs take
/// a microcode assist for each operation on a subnormal: on a Xeon this loop ran 26× slower than
/// flushed (1.3·10⁷ against 3.5·10⁸ samples per CPU-second), while on an AMD EPYC it ran at
/// 3.8·10⁸/s unflushed. The yardstick is the arithmetic, on every CPU; the synthesizer never
/// meets subnormals (it stops a bubble at −90 dB).
void BM_BaselineComplexRotation(benchmark::State& state) {
  const FlushSubnormalsToZero flush;
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
