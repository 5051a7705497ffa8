// sim/fluid/mic0_preconditioner.h — pressure projection support: modified incomplete Cholesky
// MIC(0) of a SevenPointMatrix as the preconditioner of conjugate gradients (Bridson, "Fluid
// Simulation for Computer Graphics", 2nd ed. 2015, ch. 5).
#pragma once

#include <span>
#include <vector>

#include "sim/fluid/pcg_solver.h"
#include "sim/fluid/seven_point_matrix.h"

namespace fluidsound::sim {

/// Level of the MIC(0) modification (Bridson 2015, ch. 5): 0 = plain incomplete Cholesky,
/// 1 = full modification (row sums preserved). 0.97 is the book's recommended tuning: nearly the
/// full benefit on smooth error without the instability of exactly 1.
inline constexpr double kMicTuning = 0.97;

/// A pivot below this fraction of its diagonal entry is replaced by the diagonal entry (Bridson
/// 2015, ch. 5): guards against tiny or negative pivots where MIC(0) would break down (cells
/// nearly cut off by solids, the near-singular pure-Neumann case).
inline constexpr double kMicSafety = 0.25;

/// @brief MIC(0) for a SevenPointMatrix with non-positive off-diagonals. Keeps its factor and
///        work vector between builds.
/// @note Serial triangular solves: bit-identical for any thread count.
class Mic0Preconditioner {
 public:
  /// Factors A (one pivot 1/√d per unknown, in unknown order).
  void build(const SevenPointMatrix& A);
  /// z = M⁻¹·r by the two triangular solves; `A` must be the matrix `build` was given.
  void apply(const SevenPointMatrix& A, std::span<const double> r, std::span<double> z);
  /// This factor as the callable of PcgSolver::solve (1 matrix-vector product per apply); A must
  /// outlive its use.
  PcgPreconditioner forSolve(const SevenPointMatrix& A);

 private:
  std::vector<double> precon_;   ///< 1/√(pivot) per unknown
  std::vector<double> forward_;  ///< intermediate of the two triangular solves
};

}  // namespace fluidsound::sim
