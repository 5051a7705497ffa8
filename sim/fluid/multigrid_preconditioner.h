// sim/fluid/multigrid_preconditioner.h — pressure projection support: a geometric multigrid V-cycle
// used as the preconditioner of conjugate gradients for the variational pressure matrix
// (McAdams, Sifakis & Teran 2010, "A parallel multigrid Poisson solver for fluids simulation on
// large grids").
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "sim/fluid/array3.h"
#include "sim/fluid/pcg_solver.h"
#include "sim/fluid/seven_point_matrix.h"

namespace fluidsound::sim {

/// Pre- and post-smoothing red-black Gauss–Seidel sweeps per level of a V-cycle. One sweep each
/// is the cheapest setting that keeps the V-cycle symmetric; measured on half-full tanks with a
/// sphere (32³–128³), more sweeps cut CG iterations by less than they add work.
inline constexpr int kMultigridSmoothingSweeps = 1;

/// Red-black sweep pairs on the coarsest level (at most kMultigridCoarsestCells per axis): enough
/// to reduce the error of a 4³ Poisson problem by ~1e-3, which is all a preconditioner needs.
inline constexpr int kMultigridCoarsestSweeps = 16;

/// Boundary smoothing (McAdams et al. 2010, §5): extra red-black sweep pairs, before and after
/// the coarse correction on level 0, over the unknowns within kMultigridBoundaryBand cells of a
/// face cut by a solid (0 < w < 1). Cut cells couple to their neighbours with arbitrary, possibly
/// tiny weights that the averaged coarse faces do not represent; measured at 64³ with a sphere
/// (tests/sim/fluid/multigrid_preconditioner_test.cpp), CG needed 34 iterations without these sweeps,
/// 19 with 4 and 13 with 8 (a voxelised sphere needs 13 without). The band is a few percent of the
/// unknowns, so 8 pairs cost less than one matrix-vector product per V-cycle.
inline constexpr int kMultigridBoundarySweeps = 8;
inline constexpr int kMultigridBoundaryBand = 1;

/// Coarsening stops once no axis has more cells than this.
inline constexpr int kMultigridCoarsestCells = 4;

/// @brief The V-cycle z = M⁻¹·r for the pressure matrix of PressureSolver.
///
/// Levels: level 0 is the solver grid, whose operator is the assembled matrix itself (ghost-fluid
/// θ included). Level ℓ + 1 has ⌈n/2⌉ cells per axis; a coarse cell is liquid if any child is,
/// else air if any child is air, else solid; a coarse face coefficient is the mean of its 2×2
/// child faces' coefficients divided by 4 (the 1/h² of the Laplacian at twice the spacing), and a
/// coarse liquid cell next to air gets a Dirichlet term with θ = 1 (½ across an open domain face).
/// Smoothing is red-black Gauss–Seidel; prolongation P is trilinear over the 8 nearest coarse
/// cells, renormalised over the coarse cells that are not solid (constant extension into walls,
/// value 0 in air); restriction is Pᵀ/8, so the coarse correction P·A_c⁻¹·Pᵀ/8 is symmetric.
/// Pre-smoothing sweeps red then black, post-smoothing black then red, and the coarsest level runs
/// a palindromic red, black, …, red sequence, so M⁻¹ is symmetric positive definite and CG stays
/// valid (McAdams et al. 2010, §4–5, who use it the same way).
///
/// @note Bit-identical for any thread count: every parallel loop writes disjoint entries (a colour
///       of a red-black sweep reads only the other colour) and nothing is reduced.
/// @note Deviations from the paper: red-black Gauss–Seidel instead of damped Jacobi (same
///       parallelism, better smoothing), and boundary smoothing only around solid-cut faces.
class MultigridPreconditioner {
 public:
  /// @brief Builds the coarse levels for the matrix PressureSolver assembled.
  /// @param unknownOfCell     unknown number of each solver cell, −1 if none (grid order)
  /// @param faceWeights       open fraction w_f ∈ [0, 1] per axis, size grid.faceCount(axis)
  /// @param coefficientScale  Δt/(ρh²) [m³·s/kg]: a face of weight w couples with w·scale
  void build(const Array3<std::int32_t>& unknownOfCell, const std::array<Array3f, 3>& faceWeights,
             double coefficientScale);

  /// @brief z = M⁻¹·r by one V-cycle from z = 0. `fineMatrix` must be the level-0 matrix whose
  ///        unknowns `build` was given.
  void apply(const SevenPointMatrix& fineMatrix, std::span<const double> r, std::span<double> z);

  /// Work on level 0 per apply in units of one matrix-vector product over all its unknowns: the
  /// smoothing sweeps (a red plus a black half-sweep is one), the residual, and the boundary
  /// sweeps weighted by the band's share of the unknowns. Coarse levels are not counted (each
  /// has ≤ 1/8 of the cells of the one above: ≤ 1/7 more in total).
  double fineSweepsPerApply() const;

  /// One V-cycle per apply as the callable of PcgSolver::solve, its work fineSweepsPerApply();
  /// `fineMatrix` as for apply, and it must outlive the callable's use.
  PcgPreconditioner forSolve(const SevenPointMatrix& fineMatrix);

  std::size_t levelCount() const { return levels_.size(); }
  /// Unknowns of level ℓ (ℓ = 0 is the solver grid).
  std::size_t unknowns(std::size_t level) const { return levels_[level].cellOfUnknown.size(); }

 private:
  enum class Cell : std::uint8_t { Solid, Air, Liquid };

  struct Level {
    Index3 cells{0, 0, 0};
    Array3<Cell> type;
    Array3<std::int32_t> unknownOfCell;       ///< −1 where the cell is not liquid
    std::vector<Index3> cellOfUnknown;
    std::array<Array3d, 3> faceCoefficient;   ///< w·Δt/(ρh_ℓ²) per face
    SevenPointMatrix matrix;                  ///< empty on level 0 (the caller's matrix is used)
    std::array<std::vector<std::int32_t>, 2> colour;  ///< unknowns with (i + j + k) even / odd
    std::array<std::vector<std::int32_t>, 2> boundaryColour;  ///< the cut-cell band, level 0
    std::vector<double> prolongationScale;    ///< 1/Σ trilinear weights of non-solid parents
    std::vector<double> rhs, solution, residual;
  };

  /// Level 0 from the solver's unknowns: cell types, face coefficients, unknown ↔ cell.
  static void buildFineLevel(const Array3<std::int32_t>& unknownOfCell,
                             const std::array<Array3f, 3>& faceWeights, double coefficientScale,
                             Level& fine);
  /// Level 0's boundaryColour: the unknowns within kMultigridBoundaryBand cells of a cut face.
  static void markBoundaryBand(const std::array<Array3f, 3>& faceWeights, Level& fine);
  void buildCoarseLevel(const Level& fine, Level& coarse) const;
  /// The coarse operator from the level's cell types and face coefficients (θ = 1 at air).
  static void assembleCoarseMatrix(Level& coarse);
  /// Colours, work vectors and prolongation scales of level l (once all levels exist).
  void prepareLevel(std::size_t l);
  void vCycle(std::size_t level, const SevenPointMatrix& A, std::span<const double> b,
              std::span<double> x);
  /// Level l's residual b − M·x, restricted (Pᵀ/8) into level l + 1's rhs.
  void restrictResidual(std::size_t l, const SevenPointMatrix& M, std::span<const double> b,
                        std::span<const double> x);
  /// x += P·(level l + 1's solution), M level l's operator.
  void prolongCorrection(std::size_t l, const SevenPointMatrix& M, std::span<double> x);

  std::vector<Level> levels_;
};

}  // namespace fluidsound::sim
