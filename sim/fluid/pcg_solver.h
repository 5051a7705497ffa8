// sim/fluid/pcg_solver.h — pressure projection support: a symmetric 7-point matrix over the liquid
// cells and its solver, conjugate gradients preconditioned with modified incomplete Cholesky
// MIC(0) (Bridson, "Fluid Simulation for Computer Graphics", 2nd ed. 2015, ch. 5).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace fluidsound::sim {

/// Level of the MIC(0) modification (Bridson 2015, ch. 5): 0 = plain incomplete Cholesky,
/// 1 = full modification (row sums preserved). 0.97 is the book's recommended tuning: nearly the
/// full benefit on smooth error without the instability of exactly 1.
inline constexpr double kMicTuning = 0.97;

/// A pivot below this fraction of its diagonal entry is replaced by the diagonal entry (Bridson
/// 2015, ch. 5): guards against tiny or negative pivots where MIC(0) would break down (cells
/// nearly cut off by solids, the near-singular pure-Neumann case).
inline constexpr double kMicSafety = 0.25;

/// Preconditioner of the conjugate gradients.
enum class Preconditioner {
  Mic0,       ///< modified incomplete Cholesky (Bridson 2015, ch. 5); serial triangular solves
  Multigrid,  ///< one geometric multigrid V-cycle (McAdams, Sifakis & Teran 2010); needs the grid
};

class MultigridPreconditioner;

/// A symmetric 7-point matrix on unknowns numbered in grid order (x fastest, then y, then z), so
/// that every −x/−y/−z neighbour has a smaller number than the unknown itself (required by the
/// MIC(0) sweep order). Off-diagonals are stored once, on the lower-numbered unknown.
struct SevenPointMatrix {
  std::vector<double> diagonal;                             ///< A(n, n)
  std::array<std::vector<double>, 3> plus;                  ///< A(n, n + e_a); 0 when no neighbour
  std::array<std::vector<std::int32_t>, 3> plusNeighbour;   ///< number of n + e_a, or −1
  std::array<std::vector<std::int32_t>, 3> minusNeighbour;  ///< number of n − e_a, or −1

  std::size_t size() const { return diagonal.size(); }
  /// Empties the matrix and sizes it for `n` unknowns (all entries 0, no neighbours).
  void reset(std::size_t n);
  /// y = A·x (parallel over rows; each row is summed in a fixed order).
  void multiply(std::span<const double> x, std::span<double> y) const;
};

/// Outcome of a solve (callers decide what to do with a failed one; OpenVDB's pcg::State).
struct PcgResult {
  int iterations = 0;            ///< CG iterations taken
  double relativeResidual = 0;   ///< max|r| / max|b| at exit (0 when b = 0)
  bool converged = false;        ///< relativeResidual ≤ tolerance
  int matrixVectorProducts = 0;  ///< products A·x evaluated
  /// matrixVectorProducts plus the preconditioner's work on all unknowns in units of one product:
  /// 1 per MIC(0) application (two triangular solves, each half of the 7-point stencil), and per
  /// V-cycle its level-0 smoothing sweeps and residual (MultigridPreconditioner::fineSweepsPerApply;
  /// the coarse levels, ≤ 1/7 more, are not counted).
  double matvecEquivalents = 0;
  bool operator==(const PcgResult&) const = default;
};

/// @brief Preconditioned conjugate gradients with MIC(0) for a SevenPointMatrix that is symmetric
///        positive (semi-)definite with non-positive off-diagonals. Keeps its work vectors and
///        preconditioner between calls; the preconditioner is rebuilt by every solve.
/// @note Bit-identical for any thread count: the matrix-vector product and vector updates are
///       per-entry, and dot products sum fixed blocks of kReductionBlock entries whose partial
///       sums are added in block order. The triangular solves of MIC(0) are serial.
class PcgSolver {
 public:
  /// @brief Solves A·x = b from x = 0; converged when max|r| ≤ tolerance·max|b|.
  /// @param solution  x, resized to A.size(); on return the last iterate
  PcgResult solve(const SevenPointMatrix& A, std::span<const double> rhs,
                  std::vector<double>& solution, double tolerance, int maxIterations);

  /// @brief As solve above, preconditioned by one V-cycle of `multigrid`, which must have been
  ///        built for the unknowns of A (MultigridPreconditioner::build).
  PcgResult solve(const SevenPointMatrix& A, std::span<const double> rhs,
                  std::vector<double>& solution, double tolerance, int maxIterations,
                  MultigridPreconditioner& multigrid);

  /// Entries per block of a dot product (32 KiB of doubles): large enough to amortise the task
  /// overhead, small enough that a 32³ grid still spreads over a few threads.
  static constexpr std::size_t kReductionBlock = 4096;

 private:
  /// The CG iteration; applyPreconditioner(r, z) computes z = M⁻¹·r and `workPerApply` is its
  /// cost in matrix-vector products (PcgResult::matvecEquivalents).
  template <typename Apply>
  PcgResult iterate(const SevenPointMatrix& A, std::span<const double> rhs,
                    std::vector<double>& solution, double tolerance, int maxIterations,
                    const Apply& applyPreconditioner, double workPerApply);
  void buildPreconditioner(const SevenPointMatrix& A);
  void applyPreconditioner(const SevenPointMatrix& A, std::span<const double> r,
                           std::span<double> z);
  double dot(std::span<const double> a, std::span<const double> b);

  std::vector<double> precon_;    ///< 1/√(pivot) per unknown
  std::vector<double> residual_;  ///< r = b − A·x
  std::vector<double> aux_;       ///< z = M⁻¹r, then A·s
  std::vector<double> search_;    ///< s
  std::vector<double> forward_;   ///< intermediate of the two triangular solves
  std::vector<double> partial_;   ///< per-block partial sums of a dot product
};

/// Largest |x_n| (0 for an empty vector).
double maxAbs(std::span<const double> x);

}  // namespace fluidsound::sim
