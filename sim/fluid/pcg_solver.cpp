// sim/fluid/pcg_solver.cpp — see pcg_solver.h. The algorithm is the book's (Bridson 2015, ch. 5):
// MIC(0) factor with tuning and safety constants, then PCG with a max-norm stopping test.
#include "sim/fluid/pcg_solver.h"

#include <algorithm>
#include <cmath>

#include "sim/fluid/block_parallel.h"
#include "sim/fluid/multigrid_preconditioner.h"

namespace fluidsound::sim {

void SevenPointMatrix::reset(std::size_t n) {
  diagonal.assign(n, 0.0);
  for (int a = 0; a < 3; ++a) {
    plus[a].assign(n, 0.0);
    plusNeighbour[a].assign(n, -1);
    minusNeighbour[a].assign(n, -1);
  }
}

void SevenPointMatrix::multiply(std::span<const double> x, std::span<double> y) const {
  forEachBlock(size(), PcgSolver::kReductionBlock, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      double sum = diagonal[n] * x[n];
      for (int a = 0; a < 3; ++a) {
        const std::int32_t p = plusNeighbour[a][n];
        const std::int32_t m = minusNeighbour[a][n];
        if (p >= 0) sum += plus[a][n] * x[p];
        if (m >= 0) sum += plus[a][m] * x[m];
      }
      y[n] = sum;
    }
  });
}

double maxAbs(std::span<const double> x) {
  double m = 0.0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

double PcgSolver::dot(std::span<const double> a, std::span<const double> b) {
  const std::size_t blocks = (a.size() + kReductionBlock - 1) / kReductionBlock;
  partial_.assign(blocks, 0.0);
  forEachBlock(a.size(), PcgSolver::kReductionBlock, [&](std::size_t block, std::size_t begin, std::size_t end) {
    double sum = 0.0;
    for (std::size_t n = begin; n < end; ++n) sum += a[n] * b[n];
    partial_[block] = sum;
  });
  double total = 0.0;
  for (double s : partial_) total += s;  // fixed order: block 0, 1, 2, …
  return total;
}

void PcgSolver::buildPreconditioner(const SevenPointMatrix& A) {
  const std::size_t n = A.size();
  precon_.assign(n, 0.0);
  for (std::size_t row = 0; row < n; ++row) {
    double pivot = A.diagonal[row];
    for (int a = 0; a < 3; ++a) {
      const std::int32_t m = A.minusNeighbour[a][row];
      if (m < 0) continue;
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      const double coupling = A.plus[a][m] * precon_[m];
      pivot -= coupling * coupling;
      // Modification: the fill-in that IC(0) drops, moved to the diagonal (row sums kept).
      pivot -= kMicTuning * A.plus[a][m] * (A.plus[b][m] + A.plus[c][m]) * precon_[m] * precon_[m];
    }
    if (pivot < kMicSafety * A.diagonal[row]) pivot = A.diagonal[row];
    precon_[row] = 1.0 / std::sqrt(pivot);
  }
}

void PcgSolver::applyPreconditioner(const SevenPointMatrix& A, std::span<const double> r,
                                    std::span<double> z) {
  const std::size_t n = A.size();
  forward_.resize(n);
  // Solve L·q = r (L lower triangular, L(n, n) = 1/precon(n)), increasing unknown number.
  for (std::size_t row = 0; row < n; ++row) {
    double t = r[row];
    for (int a = 0; a < 3; ++a) {
      const std::int32_t m = A.minusNeighbour[a][row];
      if (m >= 0) t -= A.plus[a][m] * precon_[m] * forward_[m];
    }
    forward_[row] = t * precon_[row];
  }
  // Solve Lᵀ·z = q, decreasing unknown number.
  for (std::size_t row = n; row-- > 0;) {
    double t = forward_[row];
    for (int a = 0; a < 3; ++a) {
      const std::int32_t p = A.plusNeighbour[a][row];
      if (p >= 0) t -= A.plus[a][row] * precon_[row] * z[p];
    }
    z[row] = t * precon_[row];
  }
}

template <typename Apply>
PcgResult PcgSolver::iterate(const SevenPointMatrix& A, std::span<const double> rhs,
                             std::vector<double>& solution, double tolerance, int maxIterations,
                             const Apply& applyPreconditioner, double workPerApply) {
  const std::size_t n = A.size();
  PcgResult result;
  solution.assign(n, 0.0);
  residual_.assign(rhs.begin(), rhs.end());
  const double rhsNorm = maxAbs(rhs);
  if (n == 0 || rhsNorm == 0.0) {
    result.converged = true;
    return result;
  }
  result.relativeResidual = 1.0;
  aux_.resize(n);
  search_.resize(n);
  applyPreconditioner(residual_, aux_);
  result.matvecEquivalents += workPerApply;
  search_ = aux_;
  double sigma = dot(aux_, residual_);
  for (int iteration = 1; iteration <= maxIterations; ++iteration) {
    A.multiply(search_, aux_);
    ++result.matrixVectorProducts;
    ++result.matvecEquivalents;
    const double curvature = dot(search_, aux_);
    if (!(curvature > 0.0)) break;  // A not positive definite along s: report, do not divide
    const double alpha = sigma / curvature;
    forEachBlock(n, PcgSolver::kReductionBlock, [&](std::size_t, std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        solution[i] += alpha * search_[i];
        residual_[i] -= alpha * aux_[i];
      }
    });
    result.iterations = iteration;
    result.relativeResidual = maxAbs(residual_) / rhsNorm;
    if (result.relativeResidual <= tolerance) {
      result.converged = true;
      break;
    }
    applyPreconditioner(residual_, aux_);
    result.matvecEquivalents += workPerApply;
    const double sigmaNew = dot(aux_, residual_);
    const double beta = sigmaNew / sigma;
    forEachBlock(n, PcgSolver::kReductionBlock, [&](std::size_t, std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) search_[i] = aux_[i] + beta * search_[i];
    });
    sigma = sigmaNew;
  }
  return result;
}

PcgResult PcgSolver::solve(const SevenPointMatrix& A, std::span<const double> rhs,
                           std::vector<double>& solution, double tolerance, int maxIterations) {
  buildPreconditioner(A);
  return iterate(
      A, rhs, solution, tolerance, maxIterations,
      [&](std::span<const double> r, std::span<double> z) { applyPreconditioner(A, r, z); },
      /*workPerApply=*/1.0);
}

PcgResult PcgSolver::solve(const SevenPointMatrix& A, std::span<const double> rhs,
                           std::vector<double>& solution, double tolerance, int maxIterations,
                           MultigridPreconditioner& multigrid) {
  return iterate(
      A, rhs, solution, tolerance, maxIterations,
      [&](std::span<const double> r, std::span<double> z) { multigrid.apply(A, r, z); },
      multigrid.fineSweepsPerApply());
}

}  // namespace fluidsound::sim
