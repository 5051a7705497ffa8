// tests/sim/fluid/multigrid_preconditioner_test.cpp — conjugate gradients preconditioned by a geometric
// multigrid V-cycle (McAdams, Sifakis & Teran 2010): symmetric (so CG is valid), reaches the
// pressure tolerance in few matrix-vector products on a tank with a free surface and a sphere,
// agrees with MIC(0) on the hydrostatic tank, and is bit-identical for any thread count.
#include "sim/fluid/multigrid_preconditioner.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <random>
#include <span>
#include <vector>

#include "sim/fluid/pressure_solver.h"
#include "sim/fluid/solid_geometry.h"

namespace fluidsound::sim {
namespace {

constexpr double kGravity = 9.81;    // m/s², standard gravity
constexpr double kDensity = 1000.0;  // kg/m³, water
constexpr double kDt = 0.01;         // s, a typical liquid substep
constexpr double kCell = 0.01;       // h [m]

/// A closed n³ box, half full (surface (n/2 + 0.3)·h: θ = 0.8 at the surface), with a sphere of
/// radius 0.2·n·h whose centre is 0.05·n·h below the surface: it cuts the surface and many faces.
struct SphereTank {
  GridGeometry grid;
  std::array<Array3f, 3> faceOpen;
  std::array<Array3f, 3> solidVelocity;
  Array3f liquidPhi;
  double surfaceHeight;

  explicit SphereTank(int n) : surfaceHeight((n / 2 + 0.3) * kCell) {
    grid = GridGeometry{{n, n, n}, kCell, {0.0, 0.0, 0.0}};
    Domain domain;
    domain.min = {0.0, 0.0, 0.0};
    domain.max = {n * kCell, n * kCell, n * kCell};
    domain.cell = kCell;
    domain.open = {false, false, false, false, false, false};
    Solid ball;
    ball.shape = Sphere{{0.4 * n * kCell, 0.45 * n * kCell, 0.5 * n * kCell}, 0.2 * n * kCell};
    const std::vector<Solid> solids{ball};
    faceOpen = faceOpenFractions(solidNodeDistance(grid, domain, solids, 0.0), grid);
    solidVelocity = solidFaceVelocity(grid, domain, solids, 0.0);
    liquidPhi = Array3f(grid.cells);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          liquidPhi(i, j, k) = float(grid.cellCentre(i, j, k)[1] - surfaceHeight);
  }

  PressureReport project(PressureSolver& solver, MacVelocity& u, Preconditioner preconditioner,
                         double tolerance) const {
    PressureSettings settings;
    settings.tolerance = tolerance;
    settings.maxIterations = 2000;
    settings.preconditioner = preconditioner;
    return solver.project(
        u, PressureProblem{liquidPhi, faceOpen, solidVelocity, grid, kDensity, kDt}, settings);
  }
};

/// Every face a uniform random velocity in [−1, 1] m/s (fixed seed): a rough right-hand side.
MacVelocity randomFlow(const GridGeometry& grid, unsigned seed) {
  MacVelocity u(grid);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> speed(-1.0f, 1.0f);
  for (int a = 0; a < 3; ++a)
    for (float& v : u[a].values()) v = speed(random);
  return u;
}

TEST(MultigridPreconditioner, VCycleIsSymmetricSoCgStaysValid) {
  // Claim: M⁻¹ is symmetric, y·M⁻¹x = x·M⁻¹y, for a matrix with cut faces (weights in (0, 1),
  // so the boundary sweeps run) and Dirichlet faces, on 12³ cells (levels 12, 6, 3). Reference:
  // the V-cycle is palindromic with restriction Pᵀ/8 (McAdams et al. 2010, §4). Tolerance:
  // rounding only, 1e-12 relative to |x|·|M⁻¹y|-sized sums of ~2000 terms.
  constexpr int kSide = 12;
  const Index3 cells{kSide, kSide, kSide};
  std::mt19937 random(5);
  std::uniform_real_distribution<float> weight(0.05f, 1.0f);
  std::array<Array3f, 3> faceWeights;
  for (int a = 0; a < 3; ++a) {
    Index3 faces = cells;
    ++faces[a];
    faceWeights[a] = Array3f(faces, 1.0f);
    for (float& w : faceWeights[a].values()) w = random() % 4 == 0 ? weight(random) : 1.0f;
  }
  Array3<std::int32_t> unknownOfCell(cells);
  for (std::size_t n = 0; n < unknownOfCell.elementCount(); ++n)
    unknownOfCell.values()[n] = std::int32_t(n);
  SevenPointMatrix A;
  A.reset(unknownOfCell.elementCount());
  for (int k = 0; k < kSide; ++k)
    for (int j = 0; j < kSide; ++j)
      for (int i = 0; i < kSide; ++i) {
        const std::int32_t row = unknownOfCell(i, j, k);
        for (int a = 0; a < 3; ++a) {
          Index3 up{i, j, k};
          ++up[a];
          const double below = faceWeights[a](i, j, k), above = faceWeights[a](up[0], up[1], up[2]);
          const bool lowerWall = (a == 0 ? i : a == 1 ? j : k) == 0;
          A.diagonal[row] += lowerWall ? 2.0 * below : below;  // open domain face: θ = ½
          if (up[a] < kSide) {
            A.diagonal[row] += above;
            A.plus[a][row] = -above;
            A.plusNeighbour[a][row] = unknownOfCell(up[0], up[1], up[2]);
            A.minusNeighbour[a][unknownOfCell(up[0], up[1], up[2])] = row;
          } else {
            A.diagonal[row] += 2.0 * above;
          }
        }
      }
  MultigridPreconditioner multigrid;
  multigrid.build(unknownOfCell, faceWeights, 1.0);
  ASSERT_EQ(multigrid.levelCount(), 3u);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<double> x(A.size()), y(A.size()), mx(A.size()), my(A.size());
  for (double& v : x) v = value(random);
  for (double& v : y) v = value(random);
  multigrid.apply(A, x, mx);
  multigrid.apply(A, y, my);
  double yMx = 0.0, xMy = 0.0, xMx = 0.0;
  for (std::size_t n = 0; n < A.size(); ++n) {
    yMx += y[n] * mx[n];
    xMy += x[n] * my[n];
    xMx += x[n] * mx[n];
  }
  EXPECT_NEAR(yMx, xMy, 1e-12 * std::abs(xMx)) << "y·M⁻¹x " << yMx << ", x·M⁻¹y " << xMy;
  EXPECT_GT(xMx, 0.0);  // positive along a random direction, as CG needs
}

TEST(MultigridPreconditioner, ReachesOneMillionthInAtMostHundredMatvecsOnA64CubedTank) {
  // Claim (our issue): MG-preconditioned CG reaches max|r| ≤ 1e-6·max|b| on a 64³ half-full tank
  // with a free surface and a sphere through it, in at most 100 matrix-vector-product
  // equivalents. Counting (PcgResult::matvecEquivalents): 1 per CG product A·s, plus per V-cycle
  // its level-0 work: 1 red-black pre-sweep, 1 residual, 1 post-sweep, and the boundary sweeps
  // weighted by the cut-cell band's share of the unknowns; the coarse levels (≤ 1/7 more) are
  // not counted. Reference: the budget of 100 (MIC(0) is printed for comparison).
  const SphereTank tank(64);
  MacVelocity mgVelocity = randomFlow(tank.grid, 17);
  MacVelocity micVelocity = mgVelocity;
  PressureSolver mgSolver, micSolver;
  const PressureReport mg = tank.project(mgSolver, mgVelocity, Preconditioner::Multigrid, 1e-6);
  const PressureReport mic = tank.project(micSolver, micVelocity, Preconditioner::Mic0, 1e-6);
  std::cout << "[ figures  ] 64³ sphere tank, MG: " << mg << "\n"
            << "[ figures  ] 64³ sphere tank, MIC(0): " << mic << "\n";
  ASSERT_TRUE(mg.converged) << mg;
  EXPECT_LE(mg.relativeResidual, 1e-6);
  EXPECT_LE(mg.matvecEquivalents, 100.0)
      << "MG-PCG: " << mg.iterations << " iterations, " << mg.matvecEquivalents
      << " matvec equivalents; MIC(0)-PCG on the same problem: " << mic.iterations
      << " iterations, " << mic.matvecEquivalents << " matvec equivalents";
}

TEST(MultigridPreconditioner, HydrostaticTankMatchesMic0Pressure) {
  // Claim: the preconditioner changes the path, not the answer: on a 32³ tank with a sphere,
  // liquid at rest under gravity gets the same pressure with MG as with MIC(0), and both are the
  // hydrostatic ρ g d. Reference: hydrostatics (exact in the variational ghost-fluid system for a
  // flat surface, Batty et al. 2007). Tolerance: at tol = 1e-8 each pressure is within the
  // columnar bound (m + 1/θ)·m·tol·ρgh ≤ 2.7e-7·ρgH of ρ g d (m = 16 layers, θ = 0.8; see
  // PressureSolver.HydrostaticTankStaysAtRest), so the two differ by ≤ 5.4e-7·ρgH; 1e-6 leaves
  // room for the flow around the sphere, which is not columnar.
  const SphereTank tank(32);
  MacVelocity mgVelocity(tank.grid), micVelocity(tank.grid);
  mgVelocity[1].fill(float(-kGravity * kDt));
  micVelocity[1].fill(float(-kGravity * kDt));
  PressureSolver mgSolver, micSolver;
  const PressureReport mg = tank.project(mgSolver, mgVelocity, Preconditioner::Multigrid, 1e-8);
  const PressureReport mic = tank.project(micSolver, micVelocity, Preconditioner::Mic0, 1e-8);
  ASSERT_TRUE(mg.converged) << mg;
  ASSERT_TRUE(mic.converged) << mic;
  const double scale = kDensity * kGravity * tank.surfaceHeight;  // ρgH [Pa]
  double difference = 0.0, hydrostatic = 0.0;
  const Index3 n = tank.grid.cells;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const double p = mgSolver.pressure()(i, j, k);
        difference = std::max(difference, std::abs(p - micSolver.pressure()(i, j, k)));
        if (p == 0.0) continue;  // not an unknown
        const double depth = tank.surfaceHeight - tank.grid.cellCentre(i, j, k)[1];
        hydrostatic = std::max(hydrostatic, std::abs(p - kDensity * kGravity * depth));
      }
  std::cout << "[ figures  ] 32³ hydrostatic sphere tank: MG " << mg << ", MIC(0) " << mic
            << ", max|p_MG − p_MIC|/(ρgH) " << difference / scale
            << ", max|p_MG − ρgd|/(ρgH) " << hydrostatic / scale << "\n";
  EXPECT_LT(difference, 1e-6 * scale);
  EXPECT_LT(hydrostatic, 1e-6 * scale);
}

TEST(MultigridPreconditioner, SolveIsBitIdenticalForAnyThreadCount) {
  // Claim: MG-PCG gives the same bits twice in a row with one solver (buffers and hierarchy
  // reused) and with one and two threads: red-black half-sweeps, transfers and residuals write
  // disjoint entries, and CG's dot products reduce fixed blocks in order. 32³ half full gives
  // ~16 000 level-0 unknowns: 4 blocks, so two threads do split the work.
  const SphereTank tank(32);
  const auto run = [&](int threads, PressureSolver& solver) {
    MacVelocity u = randomFlow(tank.grid, 23);
    PressureReport r;
    tbb::task_arena arena(threads);
    arena.execute([&] { r = tank.project(solver, u, Preconditioner::Multigrid, 1e-6); });
    return std::pair{r, solver.pressure()};
  };
  PressureSolver reused, other;
  const auto [r1, p1] = run(1, reused);
  const auto [r2, p2] = run(1, reused);
  const auto [r3, p3] = run(2, other);
  EXPECT_GT(r1.unknowns, std::int64_t(3 * PcgSolver::kReductionBlock));
  EXPECT_TRUE(r1.converged) << r1;
  EXPECT_EQ(r1, r2);
  EXPECT_EQ(r1, r3);
  const std::size_t bytes = p1.values().size() * sizeof(double);
  EXPECT_EQ(std::memcmp(p1.data(), p2.data(), bytes), 0) << "same solver, twice";
  EXPECT_EQ(std::memcmp(p1.data(), p3.data(), bytes), 0) << "1 vs 2 threads";
}

}  // namespace
}  // namespace fluidsound::sim
