// acoustics/transfer/water_modes.cpp — see water_modes.h.
#include "acoustics/transfer/water_modes.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Spectra/SymEigsShiftSolver.h>

#include "acoustics/transfer/water_helmholtz.h"

namespace fluidsound::acoustics {

namespace {

/// y = (Ã − σI)⁻¹ x for Ã = M^{-1/2} L M^{-1/2}, i.e. M^{1/2} (L − σM)⁻¹ M^{1/2} x: the
/// shift-invert operation Spectra iterates with (its "user-supplied shift-solve" interface).
class ShiftInvertOperator {
 public:
  using Scalar = double;

  ShiftInvertOperator(const WaterHelmholtz& water, double shift)
      : stiffness_(water.stiffness()), rootMass_(water.mass().cwiseSqrt()) {
    Eigen::SparseMatrix<double> shifted = stiffness_;
    for (Eigen::Index i = 0; i < shifted.rows(); ++i)
      shifted.coeffRef(i, i) -= shift * water.mass()[i];
    factor_.compute(shifted);
    if (factor_.info() != Eigen::Success)
      throw std::runtime_error("the water modes' shifted factorisation failed");
    shift_ = shift;
  }
  Eigen::Index rows() const { return rootMass_.size(); }
  Eigen::Index cols() const { return rootMass_.size(); }
  void set_shift(double sigma) {
    if (sigma != shift_) throw std::logic_error("water modes: the operator's shift is fixed");
  }
  void perform_op(const double* in, double* out) const {
    const Eigen::Map<const Eigen::VectorXd> x(in, rows());
    Eigen::Map<Eigen::VectorXd> y(out, rows());
    y = rootMass_.cwiseProduct(factor_.solve(rootMass_.cwiseProduct(x).eval()));
  }

 private:
  const Eigen::SparseMatrix<double>& stiffness_;
  Eigen::VectorXd rootMass_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
  double shift_ = 0.0;
};

/// The columns of `values`/`vectors` (eigenpairs of Ã, any order) below the cut, ascending, as
/// M-orthonormal modes φ = M^{-1/2} ψ.
WaterModes modesBelow(const Eigen::VectorXd& values, const Eigen::MatrixXd& vectors,
                      const Eigen::VectorXd& mass, double maxEigenvalue) {
  std::vector<Eigen::Index> kept;
  for (Eigen::Index j = 0; j < values.size(); ++j)
    if (values[j] < maxEigenvalue) kept.push_back(j);
  std::sort(kept.begin(), kept.end(), [&](Eigen::Index a, Eigen::Index b) {
    return values[a] < values[b];
  });
  WaterModes modes;
  modes.eigenvalue.resize(static_cast<Eigen::Index>(kept.size()));
  modes.shape.resize(mass.size(), static_cast<Eigen::Index>(kept.size()));
  const Eigen::VectorXd inverseRootMass = mass.cwiseSqrt().cwiseInverse();
  for (std::size_t c = 0; c < kept.size(); ++c) {
    modes.eigenvalue[c] = values[kept[c]];
    modes.shape.col(c) = inverseRootMass.cwiseProduct(vectors.col(kept[c]));
  }
  return modes;
}

/// At most `maxModes` of `modes`, marked incomplete when some were dropped.
WaterModes limitedTo(WaterModes modes, int maxModes) {
  if (modes.eigenvalue.size() <= maxModes) return modes;
  modes.complete = false;
  modes.eigenvalue.conservativeResize(maxModes);
  modes.shape.conservativeResize(Eigen::NoChange, maxModes);
  return modes;
}

}  // namespace

WaterModes lowestWaterModes(const WaterHelmholtz& water, double maxEigenvalue, int maxModes) {
  const Eigen::Index n = static_cast<Eigen::Index>(water.unknowns());
  if (n == 0 || !(maxEigenvalue > 0.0)) return {};
  // Spectra needs nev < n and ncv ≤ n; a frame this small is solved densely.
  constexpr Eigen::Index kDenseUnknowns = 64;
  if (n <= kDenseUnknowns) return limitedTo(lowestWaterModesDense(water, maxEigenvalue), maxModes);
  // σ just below the spectrum: every eigenvalue of L is ≥ 0, so the modes nearest σ are the
  // lowest, and L − σM is positive definite even for liquid shut in by solids.
  const double shift = -1e-3 * maxEigenvalue;
  ShiftInvertOperator op(water, shift);
  int operations = 0;
  for (Eigen::Index nev = std::min<Eigen::Index>(8, n - 2);;
       nev = std::min<Eigen::Index>(2 * nev, n - 2)) {
    const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max<Eigen::Index>(2 * nev + 1, nev + 16));
    Spectra::SymEigsShiftSolver<ShiftInvertOperator> eigs(op, nev, ncv, shift);
    eigs.init();
    eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12, Spectra::SortRule::SmallestAlge);
    operations += static_cast<int>(eigs.num_operations());
    if (eigs.info() != Spectra::CompInfo::Successful)
      throw std::runtime_error("the water modes' Lanczos iteration did not converge (" +
                               std::to_string(nev) + " modes sought)");
    const Eigen::VectorXd values = eigs.eigenvalues();
    const bool allBelow = values.maxCoeff() < maxEigenvalue;
    if (!allBelow || nev >= n - 2 || nev >= maxModes) {
      WaterModes modes = modesBelow(values, eigs.eigenvectors(), water.mass(), maxEigenvalue);
      modes.complete = !allBelow;
      modes.operations = operations;
      return limitedTo(std::move(modes), maxModes);
    }
  }
}

WaterModes lowestWaterModesDense(const WaterHelmholtz& water, double maxEigenvalue) {
  const Eigen::VectorXd rootMass = water.mass().cwiseSqrt();
  const Eigen::MatrixXd scaled = rootMass.cwiseInverse().asDiagonal() *
                                 Eigen::MatrixXd(water.stiffness()) *
                                 rootMass.cwiseInverse().asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(scaled);
  if (eigen.info() != Eigen::Success)
    throw std::runtime_error("the water modes' dense eigensolver failed");
  return modesBelow(eigen.eigenvalues(), eigen.eigenvectors(), water.mass(), maxEigenvalue);
}

}  // namespace fluidsound::acoustics
