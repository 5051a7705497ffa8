// The liquid solver against Martin & Moyce (1952) (not a speed benchmark): the collapse of a column
// a wide and 2a high at a/Δx = 10, 20 and 40, printing the simulated surge front Z(T) next to
// every measured point — the paper's table, its Fig. 3 for both column sizes, and Koshizuka &
// Oka's (1996) repeat of the experiment — with the relative error (+ = simulation ahead) and the
// experiment's lag ΔT (its T minus the simulated time to reach the same Z). No time shift; the
// summary adds, for information only, the error with Lethe's unexplained +0.175 shift.
// Data, sources, scene and front definition: tests/support/martin_moyce.h. The acceptance test
// (a/Δx = 10) is tests/sim/martin_moyce_test.cpp.
//   build/tests/fluidsound_bench --benchmark_filter=MartinMoyce
#include <benchmark/benchmark.h>
#include <oneapi/tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

#include "tests/support/martin_moyce.h"

namespace {

namespace mm = fluidsound::test::martin_moyce;

/// Simulated span [T]: past the last measured point of the table (3.33) and of Fig. 3 (3.345).
constexpr double kEndTime = 3.4;
/// The acceptance window [T].
constexpr double kFirstTime = 1.0, kLastTime = 3.0;
/// Lethe's time correction (chaos-polymtl/lethe, examples/multiphysics/dam-break/dam-break-2d.py,
/// `time_correction`), added there to the simulated T with no reason given. Reported, not used.
constexpr double kLetheShift = 0.175;

/// Largest |error| [%] of a data set in 1 ≤ T ≤ 3: as simulated, and with Lethe's shift.
struct WorstError {
  double unshifted = 0.0, shifted = 0.0;
};

/// Prints one data set against the simulation and returns its largest errors.
WorstError printComparison(const char* name, std::span<const mm::FrontSample> measured,
                           std::span<const mm::FrontSample> simulated) {
  WorstError worst;
  for (const mm::FrontSample& m : measured) {
    if (m.time <= 0.0 || m.time > simulated.back().time) continue;
    const double z = mm::frontAt(simulated, m.time);
    const double error = 100.0 * (z / m.front - 1.0);
    const double lag = m.time - mm::timeToReach(simulated, m.front);
    const bool window = m.time >= kFirstTime && m.time <= kLastTime;
    if (window) {
      worst.unshifted = std::max(worst.unshifted, std::abs(error));
      const double shifted = mm::frontAt(simulated, m.time - kLetheShift);
      worst.shifted = std::max(worst.shifted, std::abs(100.0 * (shifted / m.front - 1.0)));
    }
    std::printf("  %-26s %c %5.3f  %5.3f  %6.3f  %+6.1f %%  %+6.3f\n", name, window ? '*' : ' ', m.time,
                m.front, z, error, lag);
  }
  return worst;
}

void BM_MartinMoyceSurgeFront(benchmark::State& state) {
  const int cellsPerWidth = static_cast<int>(state.range(0));
  std::vector<mm::FrontSample> simulated;
  double seconds = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    simulated = mm::simulateFront(cellsPerWidth, kEndTime);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  std::printf("\nMartin & Moyce (1952), n^2 = 2: surge front at a/dx = %d (no time shift; * = 1 <= T <= 3)\n",
              cellsPerWidth);
  std::printf("  %-26s   %5s  %5s  %6s  %8s  %6s\n", "data", "T", "Z exp", "Z sim", "error", "lag dT");
  const WorstError table = printComparison("M&M table, a = 2.25 in", mm::kTabulatedFront, simulated);
  const WorstError large = printComparison("M&M Fig. 3, a = 2.25 in", mm::kFigureFrontLarge, simulated);
  const WorstError small = printComparison("M&M Fig. 3, a = 1.125 in", mm::kFigureFrontSmall, simulated);
  const WorstError ko = printComparison("Koshizuka & Oka 1996", mm::kKoshizukaOkaFront, simulated);

  // The experiment's lag behind the simulation at the table's stations from T = 0.84 on.
  double lagSum = 0.0, lagSquares = 0.0;
  int lags = 0;
  for (const mm::FrontSample& m : mm::kTabulatedFront) {
    if (m.time < 0.8 || m.time > simulated.back().time) continue;
    const double lag = m.time - mm::timeToReach(simulated, m.front);
    lagSum += lag;
    lagSquares += lag * lag;
    ++lags;
  }
  const double meanLag = lagSum / lags;
  const double lagSpread = std::sqrt(std::max(0.0, lagSquares / lags - meanLag * meanLag));
  std::printf("  largest |error| for 1 <= T <= 3 (acceptance: 10 %%): table %.1f %%, Fig. 3 %.1f %% / %.1f %%, "
              "Koshizuka & Oka %.1f %%\n",
              table.unshifted, large.unshifted, small.unshifted, ko.unshifted);
  std::printf("  the same with Lethe's +%.3f shift (not adopted): table %.1f %%, Fig. 3 %.1f %% / %.1f %%, "
              "Koshizuka & Oka %.1f %%\n",
              kLetheShift, table.shifted, large.shifted, small.shifted, ko.shifted);
  std::printf("  experiment's lag at the table's stations from T = 0.84 on: mean %.3f, sd %.3f (%d stations)\n",
              meanLag, lagSpread, lags);

  state.counters["cells_per_width"] = cellsPerWidth;
  state.counters["max_err_table_%"] = table.unshifted;
  state.counters["mean_lag_T"] = meanLag;
  state.counters["seconds"] = seconds;
  state.counters["threads"] = oneapi::tbb::info::default_concurrency();
}
BENCHMARK(BM_MartinMoyceSurgeFront)->Arg(10)->Arg(20)->Arg(40)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
