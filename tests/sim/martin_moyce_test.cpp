// tests/sim/martin_moyce_test.cpp — the liquid solver against an experiment: the surge front of a
// column a wide and 2a high collapsing onto a dry floor (Martin & Moyce 1952), issue 4's
// acceptance point. The data, their sources, the scene and the front's definition are in
// tests/support/martin_moyce.h; tests/bench/martin_moyce_bench.cpp prints the whole comparison
// at a/Δx = 10, 20 and 40.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/martin_moyce.h"

namespace fluidsound::sim {
namespace {

namespace mm = test::martin_moyce;

/// The acceptance window of the issue, 1 ≤ T ≤ 3 [-].
constexpr double kFirstTime = 1.0, kLastTime = 3.0;

// Claim (issue 4): at a/Δx = 10 the simulated surge front Z(T) lies within 10 % of Martin &
// Moyce's measured front at every tabulated station with 1 ≤ T ≤ 3.
// Reference: mm::kTabulatedFront, Martin & Moyce (1952) n² = 2, a = 2¼ in (source and
// transcriptions in martin_moyce.h).
// Tolerance: 10 % of Z, the figure. It is wider than the experiment's own scatter: the
// paper's table and its Fig. 3 (PySPH's digitisation) differ by up to 2.5 % for the same column,
// the 2¼ in and 1⅛ in columns by up to 4.5 % (at T ≈ 3).
// Front: where the liquid surface meets the floor (mm::surgeFrontPosition); other definitions
// move Z by < 0.1, so the definition does not decide the outcome.
// Time origin: no shift, T = 0 at the release in both. Removing a gate or diaphragm takes time
// and changes the first instants of a dam break (Aleixo, Soares-Frazão, Altinakar & Zech 2013,
// "The gate removal effect in the initial instants of the dam-break flow", IAHR World Congress),
// so the experiment's effective start may trail its T = 0; but we found no published value of that
// delay for Martin & Moyce's release, and a shift fitted to these data would make the test unable
// to fail. Lethe's dam-break example adds 0.175 to the simulated T without stating why; we do not
// adopt it (with it the Martin & Moyce points would pass, largest errors 6–8 % at a/Δx = 10 and
// 8–10 % at 20, while Koshizuka & Oka's repeat of the experiment would still miss by 12–13 %).
// Status: FAILS, expected to until the release is modelled or a published delay is found, so it
// is DISABLED_ (run it with --gtest_also_run_disabled_tests); issue 4 stays open on this point. On the
// solver with the Zhu–Bridson particle surface (no density correction) the simulated front leads
// at every station: by 9–18 % at a/Δx = 10 (7 of 11 stations outside 10 %), 11–20 % at 20 and 40;
// 40 and 80 agree within 0.015 in Z, so this is the converged inviscid answer. The experiment
// trails by a nearly constant ΔT = 0.27 ± 0.03 (a/Δx = 20–40; 13–16 ms at a = 2¼ in) from
// T = 0.84 to 3.33, while at its first station (T = 0.41, Z = 1.11) the two agree. Particle count
// (8 or 27 per cell), CFL number (1 or 0.5), APIC or FLIP, frame length and depth cells each move
// Z by < 0.03 (at a/Δx = 20), the scale a by < 0.01. An independent solver reports the same lead:
// OpenFOAM interFoam on this column, 9.8 % ahead on average and mesh-independent
// (vamseeachanta/digitalmodel, pull request 1260). tests/bench/martin_moyce_bench.cpp prints the
// current figures.
TEST(MartinMoyce, DISABLED_SurgeFrontWithinTenPercentOfExperiment) {
  const std::vector<mm::FrontSample> simulated = mm::simulateFront(10, kLastTime + mm::kFrameTime);
  int stations = 0;
  for (const mm::FrontSample& measured : mm::kTabulatedFront) {
    if (measured.time < kFirstTime || measured.time > kLastTime) continue;
    ++stations;
    const double front = mm::frontAt(simulated, measured.time);
    EXPECT_NEAR(front, measured.front, 0.10 * measured.front)
        << "T = " << measured.time << ": simulated Z = " << front << ", Martin & Moyce Z = "
        << measured.front << " (" << 100.0 * (front / measured.front - 1.0) << " %)";
  }
  EXPECT_EQ(stations, 11);
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
