// tests/sim/fluid/pcg_solver_test.cpp — MIC(0)-preconditioned conjugate gradients (Bridson 2015,
// ch. 5) on 7-point Laplacians with known solutions, and the solver with a preconditioner callable
// of the caller's.
#include "sim/fluid/pcg_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <span>
#include <vector>

#include "sim/fluid/mic0_preconditioner.h"

namespace fluidsound::sim {
namespace {

/// The 7-point Laplacian (diagonal 6, neighbours −1) on an n³ block of unknowns with Dirichlet
/// value 0 all around, numbered x fastest.
SevenPointMatrix dirichletLaplacian(int n) {
  SevenPointMatrix A;
  A.reset(static_cast<std::size_t>(n) * n * n);
  const auto index = [n](int i, int j, int k) { return std::int32_t((k * n + j) * n + i); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::int32_t row = index(i, j, k);
        A.diagonal[row] = 6.0;
        const int c[3] = {i, j, k};
        for (int a = 0; a < 3; ++a) {
          int up[3] = {i, j, k}, down[3] = {i, j, k};
          ++up[a];
          --down[a];
          if (c[a] + 1 < n) {
            A.plus[a][row] = -1.0;
            A.plusNeighbour[a][row] = index(up[0], up[1], up[2]);
          }
          if (c[a] > 0) A.minusNeighbour[a][row] = index(down[0], down[1], down[2]);
        }
      }
  return A;
}

/// PCG preconditioned by MIC(0) of A.
PcgResult solveWithMic0(const SevenPointMatrix& A, std::span<const double> b,
                        std::vector<double>& x, double tolerance, int maxIterations) {
  Mic0Preconditioner mic0;
  mic0.build(A);
  PcgSolver solver;
  return solver.solve(A, b, x, PcgStop{tolerance, maxIterations}, mic0.forSolve(A));
}

/// A smooth, non-symmetric test solution x*(n): not an eigenvector, so CG has work to do.
std::vector<double> knownSolution(std::size_t size) {
  std::vector<double> x(size);
  for (std::size_t n = 0; n < size; ++n) x[n] = std::sin(0.37 * double(n)) + 0.01 * double(n % 7);
  return x;
}

TEST(PcgSolver, MicIsExactOnAChainSoCgConvergesInOneIteration) {
  // Claim: on a 1-D chain (tridiagonal matrix) incomplete Cholesky drops no fill-in and the
  // modification term is empty, so MIC(0) is the exact Cholesky factor and PCG converges in one
  // iteration. Reference: Bridson 2015, ch. 5 (IC(0) keeps the sparsity of A). Tolerance: the
  // solve's own tolerance 1e-12 on the max-norm residual.
  constexpr int kLength = 50;
  SevenPointMatrix A;
  A.reset(kLength);
  for (int n = 0; n < kLength; ++n) {
    A.diagonal[n] = 2.0;
    if (n + 1 < kLength) {
      A.plus[0][n] = -1.0;
      A.plusNeighbour[0][n] = n + 1;
    }
    if (n > 0) A.minusNeighbour[0][n] = n - 1;
  }
  const std::vector<double> expected = knownSolution(kLength);
  std::vector<double> b(kLength), x;
  A.multiply(expected, b);
  const PcgResult r = solveWithMic0(A, b, x, 1e-12, 10);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 1) << "residual " << r.relativeResidual;
}

TEST(PcgSolver, SolvesThreeDimensionalPoissonToTheRequestedResidual) {
  // Claim: the solve stops with max|r| ≤ tol·max|b| and then the error is bounded by
  // ‖A⁻¹‖∞·max|r|. Reference: for this M-matrix, φ(i) = i(n + 1 − i)/2 (1-based i) satisfies
  // A·φ = 1, so ‖A⁻¹‖∞ ≤ max φ = (n + 1)²/8. Tolerance: that bound times tol·max|b|, doubled
  // for the drift between the recursively updated and the true residual (rounding, ~1e-14 here).
  constexpr int kSide = 16;
  constexpr double kTolerance = 1e-8;
  const SevenPointMatrix A = dirichletLaplacian(kSide);
  const std::vector<double> expected = knownSolution(A.size());
  std::vector<double> b(A.size()), x;
  A.multiply(expected, b);
  const PcgResult r = solveWithMic0(A, b, x, kTolerance, 1000);
  ASSERT_TRUE(r.converged) << "iterations " << r.iterations << ", residual " << r.relativeResidual;
  EXPECT_LE(r.relativeResidual, kTolerance);
  EXPECT_EQ(r.matrixVectorProducts, r.iterations);
  const double inverseNormBound = (kSide + 1.0) * (kSide + 1.0) / 8.0;
  const double errorBound = 2.0 * inverseNormBound * kTolerance * maxAbs(b);
  double error = 0.0;
  for (std::size_t n = 0; n < x.size(); ++n) error = std::max(error, std::abs(x[n] - expected[n]));
  EXPECT_LE(error, errorBound) << "iterations " << r.iterations;
  std::cout << "[ figures  ] 16³ Dirichlet Laplacian: " << r.iterations << " iterations, residual "
            << r.relativeResidual << ", max error " << error << " (bound " << errorBound << ")\n";
}

TEST(PcgSolver, ZeroRightHandSideNeedsNoIterations) {
  // Claim: b = 0 gives x = 0 at once, reported as converged with zero iterations.
  const SevenPointMatrix A = dirichletLaplacian(4);
  std::vector<double> b(A.size(), 0.0), x;
  const PcgResult r = solveWithMic0(A, b, x, 1e-6, 100);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(maxAbs(x), 0.0);
}

TEST(PcgSolver, ReportsFailureAtTheIterationLimit) {
  // Claim: a solve cut off before convergence says so (converged false, the iterations used and
  // the residual reached); the caller decides. A 16³ Poisson problem needs far more than 2
  // iterations to reach 1e-12 (CG reduces the error by at most a constant factor per iteration).
  const SevenPointMatrix A = dirichletLaplacian(16);
  const std::vector<double> expected = knownSolution(A.size());
  std::vector<double> b(A.size()), x;
  A.multiply(expected, b);
  const PcgResult r = solveWithMic0(A, b, x, 1e-12, 2);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_GT(r.relativeResidual, 1e-12);
}

TEST(PcgSolver, AppliesTheCallersPreconditionerAndCountsItsWork) {
  // Claim: the solver runs with any callable z = M⁻¹·r: Jacobi (z = r / diag A) reaches the
  // tolerance on the 3-D Poisson problem, is called once per iteration (once before the first,
  // none after the converged one), and each call adds its stated work to matvecEquivalents.
  constexpr double kTolerance = 1e-8;
  constexpr double kJacobiWork = 0.25;  // an arbitrary cost, to see it counted
  const SevenPointMatrix A = dirichletLaplacian(8);
  const std::vector<double> expected = knownSolution(A.size());
  std::vector<double> b(A.size()), x;
  A.multiply(expected, b);
  int applications = 0;
  const PcgPreconditioner jacobi{[&](std::span<const double> r, std::span<double> z) {
                                   ++applications;
                                   for (std::size_t n = 0; n < r.size(); ++n)
                                     z[n] = r[n] / A.diagonal[n];
                                 },
                                 kJacobiWork};
  PcgSolver solver;
  const PcgResult r = solver.solve(A, b, x, PcgStop{kTolerance, 1000}, jacobi);
  ASSERT_TRUE(r.converged);
  EXPECT_LE(r.relativeResidual, kTolerance);
  EXPECT_EQ(applications, r.iterations);
  EXPECT_DOUBLE_EQ(r.matvecEquivalents, r.matrixVectorProducts + kJacobiWork * applications);
  // Jacobi on a constant diagonal is CG itself: more iterations than MIC(0) needs.
  std::vector<double> xMic;
  EXPECT_GT(r.iterations, solveWithMic0(A, b, xMic, kTolerance, 1000).iterations);
}

}  // namespace
}  // namespace fluidsound::sim
