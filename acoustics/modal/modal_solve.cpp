// acoustics/modal/modal_solve.cpp — see modal_solve.h.
#include "acoustics/modal/modal_solve.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>

namespace fluidsound::acoustics {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// y = (K − σM)⁻¹ x by one CHOLMOD supernodal Cholesky factorisation: the shift-solve operation
/// Spectra's shift-invert mode iterates with (set_shift, perform_op, rows, cols).
class ShiftedCholeskySolve {
 public:
  using Scalar = double;

  ShiftedCholeskySolve(const SparseMatrix& stiffness, const SparseMatrix& mass)
      : stiffness_(stiffness), mass_(mass) {
    factor_.cholmod().print = 0;  // library code never prints; failures are reported by throwing
  }

  Eigen::Index rows() const { return stiffness_.rows(); }
  Eigen::Index cols() const { return stiffness_.cols(); }

  /// Factorises K − σM. Called by the solver's constructor.
  void set_shift(double shift) {
    const SparseMatrix shifted = stiffness_ - shift * mass_;
    factor_.compute(shifted);
    if (factor_.info() != Eigen::Success)
      throw std::runtime_error(
          "modal solve: K - sigma*M is not positive definite (CHOLMOD), sigma = " +
          std::to_string(shift) + " rad^2/s^2");
  }

  void perform_op(const double* in, double* out) const {
    const Eigen::Map<const Eigen::VectorXd> x(in, rows());
    Eigen::Map<Eigen::VectorXd> y(out, rows());
    y = factor_.solve(x);
  }

 private:
  const SparseMatrix& stiffness_;
  const SparseMatrix& mass_;
  Eigen::CholmodSupernodalLLT<SparseMatrix> factor_;
};

/// Every eigenpair of a small system by Eigen's dense generalised solver (M-orthonormal vectors).
GeneralisedEigenpairs denseEigenpairs(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                      int count) {
  const Eigen::MatrixXd denseStiffness(stiffness);
  const Eigen::MatrixXd denseMass(mass);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(denseStiffness, denseMass);
  if (eigen.info() != Eigen::Success)
    throw std::runtime_error("modal solve: the dense generalised eigensolver failed");
  const Eigen::Index kept = std::min<Eigen::Index>(count, stiffness.rows());
  return {eigen.eigenvalues().head(kept), eigen.eigenvectors().leftCols(kept), 0};
}

}  // namespace

GeneralisedEigenpairs lowestEigenpairs(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                       int count, double shift) {
  const Eigen::Index dofs = stiffness.rows();
  if (count < 1 || dofs == 0) return {};
  if (dofs <= kDenseDofs) return denseEigenpairs(stiffness, mass, count);

  // Spectra's advice: ncv ≥ 2·nev; a floor of 20 extra vectors helps the first few pairs.
  constexpr Eigen::Index kExtraLanczosVectors = 20;
  constexpr int kMaxRestarts = 1000;
  constexpr double kTolerance = 1e-10;  // relative accuracy of each Ritz value ν
  // Spectra needs nev < ncv ≤ dofs.
  const Eigen::Index nev = std::min<Eigen::Index>(count, dofs - 1);
  const Eigen::Index ncv =
      std::min<Eigen::Index>(dofs, std::max(2 * nev + 1, nev + kExtraLanczosVectors));
  ShiftedCholeskySolve op(stiffness, mass);
  Spectra::SparseSymMatProd<double> massProduct(mass);
  Spectra::SymGEigsShiftSolver<ShiftedCholeskySolve, Spectra::SparseSymMatProd<double>,
                               Spectra::GEigsMode::ShiftInvert>
      eigs(op, massProduct, nev, ncv, shift);
  eigs.init();  // Spectra's fixed-seed start vector: deterministic
  eigs.compute(Spectra::SortRule::LargestMagn, kMaxRestarts, kTolerance,
               Spectra::SortRule::SmallestAlge);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("modal solve: shift-invert Lanczos did not converge for " +
                             std::to_string(nev) + " modes of " + std::to_string(dofs) + " DOFs");
  return {eigs.eigenvalues(), eigs.eigenvectors(), static_cast<int>(eigs.num_operations())};
}

}  // namespace fluidsound::acoustics
