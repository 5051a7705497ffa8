// sim/fluid/pcg_solver.h — pressure projection support: preconditioned conjugate gradients for a
// SevenPointMatrix with a max-norm stopping test (Bridson, "Fluid Simulation for Computer
// Graphics", 2nd ed. 2015, ch. 5). The preconditioner is a callable the caller supplies
// (mic0_preconditioner.h, multigrid_preconditioner.h).
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "sim/fluid/seven_point_matrix.h"

namespace fluidsound::sim {

/// Outcome of a solve (callers decide what to do with a failed one; OpenVDB's pcg::State).
struct PcgResult {
  int iterations = 0;            ///< CG iterations taken
  double relativeResidual = 0;   ///< max|r| / max|b| at exit (0 when b = 0)
  bool converged = false;        ///< relativeResidual ≤ tolerance
  int matrixVectorProducts = 0;  ///< products A·x evaluated
  /// matrixVectorProducts plus the preconditioner's work on all unknowns in units of one product
  /// (PcgPreconditioner::workPerApply per application).
  double matvecEquivalents = 0;
  bool operator==(const PcgResult&) const = default;
};

/// When a solve stops.
struct PcgStop {
  double tolerance = 1e-6;   ///< converged when max|r| ≤ tolerance·max|b| (relative, max-norm)
  int maxIterations = 1000;  ///< iteration limit
};

/// z = M⁻¹·r for a symmetric positive definite M ≈ A (CG stays valid only then), and its cost.
struct PcgPreconditioner {
  std::function<void(std::span<const double> r, std::span<double> z)> apply;
  /// Work of one apply in units of one matrix-vector product over all unknowns: 1 for MIC(0)
  /// (two triangular solves, each half of the 7-point stencil); the level-0 work of a V-cycle
  /// for the multigrid (MultigridPreconditioner::fineSweepsPerApply).
  double workPerApply = 1.0;
};

/// @brief Preconditioned conjugate gradients for a SevenPointMatrix that is symmetric positive
///        (semi-)definite. Keeps its work vectors between calls.
/// @note Bit-identical for any thread count when the preconditioner is: the matrix-vector
///       product and vector updates are per-entry, and dot products sum fixed blocks of
///       kUnknownBlock entries whose partial sums are added in block order.
class PcgSolver {
 public:
  /// @brief Solves A·x = b from x = 0, preconditioned by `preconditioner` (built for A).
  /// @param solution  x, resized to A.size(); on return the last iterate
  PcgResult solve(const SevenPointMatrix& A, std::span<const double> rhs,
                  std::vector<double>& solution, const PcgStop& stop,
                  const PcgPreconditioner& preconditioner);

  /// Entries per block of a dot product (seven_point_matrix.h).
  static constexpr std::size_t kReductionBlock = kUnknownBlock;

 private:
  double dot(std::span<const double> a, std::span<const double> b);

  std::vector<double> residual_;  ///< r = b − A·x
  std::vector<double> aux_;       ///< z = M⁻¹r, then A·s
  std::vector<double> search_;    ///< s
  std::vector<double> partial_;   ///< per-block partial sums of a dot product
};

/// Largest |x_n| (0 for an empty vector).
double maxAbs(std::span<const double> x);

}  // namespace fluidsound::sim
