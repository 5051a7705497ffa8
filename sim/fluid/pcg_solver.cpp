// sim/fluid/pcg_solver.cpp — see pcg_solver.h. The algorithm is the book's (Bridson 2015, ch. 5):
// PCG with a max-norm stopping test.
#include "sim/fluid/pcg_solver.h"

#include <algorithm>
#include <cmath>

#include "sim/fluid/block_parallel.h"

namespace fluidsound::sim {

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

PcgResult PcgSolver::solve(const SevenPointMatrix& A, std::span<const double> rhs,
                           std::vector<double>& solution, const PcgStop& stop,
                           const PcgPreconditioner& preconditioner) {
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
  preconditioner.apply(residual_, aux_);
  result.matvecEquivalents += preconditioner.workPerApply;
  search_ = aux_;
  double sigma = dot(aux_, residual_);
  for (int iteration = 1; iteration <= stop.maxIterations; ++iteration) {
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
    if (result.relativeResidual <= stop.tolerance) {
      result.converged = true;
      break;
    }
    preconditioner.apply(residual_, aux_);
    result.matvecEquivalents += preconditioner.workPerApply;
    const double sigmaNew = dot(aux_, residual_);
    const double beta = sigmaNew / sigma;
    forEachBlock(n, PcgSolver::kReductionBlock, [&](std::size_t, std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) search_[i] = aux_[i] + beta * search_[i];
    });
    sigma = sigmaNew;
  }
  return result;
}

}  // namespace fluidsound::sim
