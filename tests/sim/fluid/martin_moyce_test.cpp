// tests/sim/martin_moyce_test.cpp — the liquid solver against an experiment: the surge front of a
// column a wide and 2a high collapsing onto a dry floor (Martin & Moyce 1952), issue 4's
// acceptance point. The data, their sources, the scene and the front's definition are in
// tests/support/martin_moyce.h; tests/bench/martin_moyce_bench.cpp prints the whole comparison
// at a/Δx = 10, 20 and 40.
// The comparison with the experiment delays the simulated front by one fitted constant (the
// first test below says why, with its sources); the second checks the grid resolves the front.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <vector>

#include "support/martin_moyce.h"

namespace fluidsound::sim {
namespace {

namespace mm = test::martin_moyce;

/// The acceptance window of the issue, 1 ≤ T ≤ 3 [-].
constexpr double kFirstTime = 1.0, kLastTime = 3.0;

/// Least-squares slope dZ/dT [-] of the history's samples with first ≤ T ≤ last.
double frontSlope(std::span<const mm::FrontSample> history, double first, double last) {
  double n = 0, st = 0, sz = 0, stt = 0, stz = 0;
  for (const mm::FrontSample& s : history) {
    if (s.time < first - 1e-9 || s.time > last + 1e-9) continue;
    n += 1, st += s.time, sz += s.front, stt += s.time * s.time, stz += s.time * s.front;
  }
  return (n * stz - st * sz) / (n * stt - st * st);
}

/// RMS over the tabulated stations with kFirstTime ≤ T ≤ kLastTime of the relative error of the
/// simulated front delayed by `shift`: Z_sim(T − shift) against the measured Z(T) [-].
double rmsRelativeError(std::span<const mm::FrontSample> simulated, double shift) {
  double sum = 0.0;
  int stations = 0;
  for (const mm::FrontSample& measured : mm::kTabulatedFront) {
    if (measured.time < kFirstTime || measured.time > kLastTime) continue;
    const double error = mm::frontAt(simulated, measured.time - shift) / measured.front - 1.0;
    sum += error * error;
    ++stations;
  }
  return std::sqrt(sum / stations);
}

/// The delay ΔT [-] that minimises Σ (Z_sim(T − ΔT) − Z(T))² over the same stations: a scan in
/// steps of 0.001 over 0 … 0.6 (the sum is smooth; 0.001 is far below the test's bounds).
double bestShift(std::span<const mm::FrontSample> simulated) {
  double best = 0.0, bestSum = std::numeric_limits<double>::infinity();
  for (int step = 0; step <= 600; ++step) {
    const double shift = 0.001 * step;
    double sum = 0.0;
    for (const mm::FrontSample& measured : mm::kTabulatedFront) {
      if (measured.time < kFirstTime || measured.time > kLastTime) continue;
      const double d = mm::frontAt(simulated, measured.time - shift) - measured.front;
      sum += d * d;
    }
    if (sum < bestSum) bestSum = sum, best = shift;
  }
  return best;
}

// Claim (issue 16 §8): at a/Δx = 20 the simulated surge front matches Martin & Moyce's measured
// front once delayed by one constant ΔT, the lead inviscid codes show: (a) the least-squares ΔT
// lies in [0.15, 0.32], (b) the RMS relative error of Z after that shift is ≤ 4 % over the
// stations with 1 ≤ T ≤ 3, and (c) the front's slope dZ/dT on 1.43 ≤ T ≤ 3.33 is 1.32 ± 0.15.
// Reference: mm::kTabulatedFront, Martin & Moyce (1952) Table 2, n² = 2, a = 2¼ in (sources and
// transcriptions in martin_moyce.h); the slope 1.32 is the data's own over those stations
// (least squares: printed below as "measured slope").
// Why a shift: the experiment's effective start trails its T = 0 (the release of the column
// takes time; Aleixo, Soares-Frazão, Altinakar & Zech 2013 on the gate removal effect), and
// inviscid computations lead the data by a nearly constant ΔT: Koshizuka & Oka's own MPS
// computation (1996, Nucl. Sci. Eng. 123, 421–434) leads Table 2 by ΔT ≈ 0.26; Lethe's published
// dam-break case (chaos-polymtl/lethe, examples/multiphysics/dam-break) shifts its simulated T
// by 0.175; an interFoam run of this column is ≈ 10 % ahead (martin_moyce.h). The bounds
// [0.15, 0.32] hold both published shifts with margin; a shift outside them would mean a
// different front speed, not a release delay.
// Tolerance: 4 % RMS, the figure: above the experiment's own scatter (Table 2 against
// its Fig. 3, PySPH's digitisation: up to 2.5 %). Slope ± 0.15: the issue's, about 11 % of it.
// Fit window: the acceptance window of issue 4 (1 ≤ T ≤ 3, 11 stations), fixed before the fit.
// Measured (3 December 2026): ΔT = 0.256, RMS 1.76 % after it (14.1 % without), slope 1.401
// against the data's 1.319; 8 s on 2 busy cores.
TEST(MartinMoyce, SurgeFrontMatchesTheExperimentAfterOneConstantDelay) {
  const std::vector<mm::FrontSample> simulated = mm::simulateFront(20, 3.33 + mm::kFrameTime);
  const double shift = bestShift(simulated);
  const double rms = rmsRelativeError(simulated, shift);
  const double slope = frontSlope(simulated, 1.43, 3.33);
  const double measuredSlope = frontSlope(mm::kTabulatedFront, 1.43, 3.33);
  std::printf(
      "[ measured ] a/dx = 20: best delay %.3f, RMS relative error %.2f %% after it "
      "(%.2f %% without), slope dZ/dT %.3f on 1.43 <= T <= 3.33 (measured slope %.3f)\n",
      shift, 100.0 * rms, 100.0 * rmsRelativeError(simulated, 0.0), slope, measuredSlope);
  EXPECT_GE(shift, 0.15);
  EXPECT_LE(shift, 0.32);
  EXPECT_LE(rms, 0.04);
  EXPECT_NEAR(slope, 1.32, 0.15);
}

// Claim: a/Δx = 10 resolves the front, so the comparison above measures the model, not the grid:
// halving the cells moves Z by less than one coarse cell at every station with 1 ≤ T ≤ 3.
// Reference: the same simulation at a/Δx = 20 (convergence between two resolutions; STYLE.md).
// Tolerance: 0.1 in Z = one cell of the coarse grid (a/10): the front is read from a surface
// sampled at cell centres and reconstructed from particles within 1.5 cells, so agreement to a
// cell is what "resolved" can mean here. (Measured: ≤ 0.06, largest at T ≈ 3; 20 → 40 ≤ 0.03.)
TEST(MartinMoyce, SurgeFrontResolvedAtTenCellsPerWidth) {
  const std::vector<mm::FrontSample> coarse = mm::simulateFront(10, kLastTime + mm::kFrameTime);
  const std::vector<mm::FrontSample> fine = mm::simulateFront(20, kLastTime + mm::kFrameTime);
  const double coarseCell = 1.0 / 10;  // a/Δx = 10, in units of a
  for (const mm::FrontSample& measured : mm::kTabulatedFront) {
    if (measured.time < kFirstTime || measured.time > kLastTime) continue;
    const double zCoarse = mm::frontAt(coarse, measured.time), zFine = mm::frontAt(fine, measured.time);
    EXPECT_NEAR(zCoarse, zFine, coarseCell)
        << "T = " << measured.time << ": Z = " << zCoarse << " at a/Δx = 10, " << zFine << " at 20";
  }
}

}  // namespace
}  // namespace fluidsound::sim
