// acoustics/modal/modal_solve.cpp — see modal_solve.h.
#include "acoustics/modal/modal_solve.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#include <Spectra/SymGEigsShiftSolver.h>

namespace fluidsound::acoustics {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// y = (K − σM)⁻¹ x with the solver's CHOLMOD factor: the shift-solve operation Spectra's
/// shift-invert mode iterates with (set_shift, perform_op, rows, cols). The factor is made once,
/// by LowestEigenpairsSolver, for its shift; set_shift only checks that Spectra asks for it.
class ShiftedCholeskySolve {
 public:
  using Scalar = double;
  ShiftedCholeskySolve(const Eigen::CholmodSupernodalLLT<SparseMatrix>& factor, Eigen::Index size, double shift)
      : factor_(factor), size_(size), shift_(shift) {}
  Eigen::Index rows() const { return size_; }
  Eigen::Index cols() const { return size_; }
  void set_shift(double shift) {
    if (shift != shift_) throw std::logic_error("modal solve: the factor is for another shift");
  }
  void perform_op(const double* in, double* out) const {
    Eigen::Map<Eigen::VectorXd>(out, size_) = factor_.solve(Eigen::Map<const Eigen::VectorXd>(in, size_));
  }

 private:
  const Eigen::CholmodSupernodalLLT<SparseMatrix>& factor_;
  Eigen::Index size_;
  double shift_;
};

/// y = M x from M's lower triangle, its explicit zeros pruned (the assembly keeps K's pattern, three
/// times M's nonzeros): Spectra's B operation. The lower triangle only, as Spectra's own
/// SparseSymMatProd: M's assembled upper triangle differs in the last bits, and a product that is
/// not exactly symmetric spoils the M-orthogonality of the highest pairs (measured: 4e-5 relative
/// error of pair 100 of a 108-unknown box with the full product, 1e-8 with the triangle).
class MassProduct {
 public:
  using Scalar = double;
  explicit MassProduct(const SparseMatrix& mass) : mass_(mass) {}
  Eigen::Index rows() const { return mass_.rows(); }
  Eigen::Index cols() const { return mass_.cols(); }
  void perform_op(const double* in, double* out) const {
    Eigen::Map<Eigen::VectorXd>(out, rows()).noalias() = mass_.selfadjointView<Eigen::Lower>() *
                                                Eigen::Map<const Eigen::VectorXd>(in, cols());
  }

 private:
  const SparseMatrix& mass_;
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

struct LowestEigenpairsSolver::Factor {
  Eigen::CholmodSupernodalLLT<SparseMatrix> cholesky;
  SparseMatrix mass;  // M without explicit zeros
};

LowestEigenpairsSolver::LowestEigenpairsSolver(const SparseMatrix& stiffness, const SparseMatrix& mass, double shift)
    : stiffness_(stiffness), mass_(mass), shift_(shift) {
  if (stiffness.rows() <= kDenseDofs) return;
  factor_ = std::make_unique<Factor>();
  factor_->cholesky.cholmod().print = 0;  // library code never prints; failures are reported by throwing
  factor_->cholesky.compute(stiffness - shift * mass);
  if (factor_->cholesky.info() != Eigen::Success)
    throw std::runtime_error("modal solve: K - sigma*M is not positive definite (CHOLMOD), sigma = " +
                             std::to_string(shift) + " rad^2/s^2");
  factor_->mass = mass.pruned();
}

LowestEigenpairsSolver::~LowestEigenpairsSolver() = default;

GeneralisedEigenpairs LowestEigenpairsSolver::lowest(int count) const {
  const Eigen::Index dofs = stiffness_.rows();
  if (count < 1 || dofs == 0) return {};
  if (!factor_) return denseEigenpairs(stiffness_, mass_, count);

  // Spectra's advice: ncv ≥ 2·nev; a floor of 20 extra vectors helps the first few pairs.
  constexpr Eigen::Index kExtraLanczosVectors = 20;
  constexpr int kMaxRestarts = 1000;
  constexpr double kTolerance = 1e-10;  // relative accuracy of each Ritz value ν
  // Spectra needs nev < ncv ≤ dofs.
  const Eigen::Index nev = std::min<Eigen::Index>(count, dofs - 1);
  const Eigen::Index ncv = std::min<Eigen::Index>(dofs, std::max(2 * nev + 1, nev + kExtraLanczosVectors));
  ShiftedCholeskySolve op(factor_->cholesky, dofs, shift_);
  MassProduct massProduct(factor_->mass);
  Spectra::SymGEigsShiftSolver<ShiftedCholeskySolve, MassProduct, Spectra::GEigsMode::ShiftInvert> eigs(
      op, massProduct, nev, ncv, shift_);
  eigs.init();  // Spectra's fixed-seed start vector: deterministic
  eigs.compute(Spectra::SortRule::LargestMagn, kMaxRestarts, kTolerance, Spectra::SortRule::SmallestAlge);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("modal solve: shift-invert Lanczos did not converge for " + std::to_string(nev) +
                             " modes of " + std::to_string(dofs) + " DOFs");
  return {eigs.eigenvalues(), eigs.eigenvectors(), static_cast<int>(eigs.num_operations())};
}

GeneralisedEigenpairs lowestEigenpairs(const SparseMatrix& stiffness, const SparseMatrix& mass, int count,
                                       double shift) {
  return LowestEigenpairsSolver(stiffness, mass, shift).lowest(count);
}

}  // namespace fluidsound::acoustics
