// acoustics/modal/modal_solve.h — the lowest eigenpairs of the sparse generalised eigenproblem
// K x = λ M x of a sounding solid, by shift-invert Lanczos (Spectra, MPL-2.0) with a CHOLMOD
// factorisation of K − σM (SuiteSparse, LGPL-2.1+) (shared solids.md §3.3).
#pragma once

#include <memory>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace fluidsound::acoustics {

/// Systems with at most this many DOFs are solved densely (a single voxel has 24).
inline constexpr int kDenseDofs = 96;

/// Eigenpairs of K x = λ M x, lowest first.
struct GeneralisedEigenpairs {
  Eigen::VectorXd eigenvalues;   ///< λ_j = ω_j² [rad²/s²], ascending
  Eigen::MatrixXd eigenvectors;  ///< DOFs × pairs, M-orthonormal columns (xᵀ M x = 1)
  int operations = 0;            ///< shift-invert solves the Lanczos iteration took
};

/// K − σM factorised once, for as many requests of the lowest eigenpairs as needed (a body's
/// modal analysis asks for a few, then more until it passes the highest audible frequency).
class LowestEigenpairsSolver {
 public:
  /// @brief Factorises K − σM (CHOLMOD's supernodal Cholesky) and keeps M without its explicit
  ///        zeros for the products. The matrices must outlive the solver.
  /// @throws std::runtime_error when K − σM is not positive definite
  LowestEigenpairsSolver(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                         double shift);
  ~LowestEigenpairsSolver();
  LowestEigenpairsSolver(const LowestEigenpairsSolver&) = delete;
  LowestEigenpairsSolver& operator=(const LowestEigenpairsSolver&) = delete;

  /// @brief The `count` lowest pairs, as lowestEigenpairs.
  GeneralisedEigenpairs lowest(int count) const;

 private:
  struct Factor;
  const Eigen::SparseMatrix<double>& stiffness_;
  const Eigen::SparseMatrix<double>& mass_;
  double shift_;
  std::unique_ptr<Factor> factor_;  // none for a system solved densely
};

/// @brief The `count` eigenpairs of K x = λ M x nearest above the shift σ, i.e. the lowest ones
///        when σ lies below the spectrum.
/// @details Spectra's SymGEigsShiftSolver in shift-invert mode iterates (K − σM)⁻¹ M x = ν x with
///          ν = 1/(λ − σ), M-orthogonal Lanczos vectors and Spectra's fixed-seed start vector, so
///          the result is the same bits on every run. K − σM is factorised once by CHOLMOD's
///          supernodal Cholesky; no other factorisation is tried. Up to kDenseDofs DOFs (a few
///          voxels, where Lanczos cannot return all pairs) Eigen's dense generalised solver is
///          used instead.
/// @param stiffness  K [N/m], symmetric positive semi-definite
/// @param mass       M [kg], symmetric positive definite, same size
/// @param count      pairs wanted, ≥ 1; at most all of them are returned up to kDenseDofs DOFs,
///                   at most DOFs − 1 beyond (Lanczos)
/// @param shift      σ [rad²/s²], < every eigenvalue, so K − σM is positive definite
/// @throws std::runtime_error when K − σM is not positive definite or Lanczos does not converge
GeneralisedEigenpairs lowestEigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                                       const Eigen::SparseMatrix<double>& mass, int count,
                                       double shift);

}  // namespace fluidsound::acoustics
