// tests/acoustics/modal/modal_solve_test.cpp — the lowest eigenpairs of K x = λ M x by
// shift-invert Lanczos with CHOLMOD (modal_solve.h): what the dense solver finds, M-orthonormal,
// the same bits on every run, and a refusal when K − σM is not positive definite.
#include "acoustics/modal/modal_solve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "acoustics/modal/elastic_matrices.h"

namespace fluidsound::acoustics {
namespace {

constexpr int kRigidModes = 6;

/// A free 4 × 3 × 2 steel box of 1 cm cells: 60 nodes, 180 DOFs (over kDenseDofs, so Lanczos).
ElasticMatrices freeBox() {
  return assembleElasticMatrices(hexMesh(voxelBox({0.04, 0.03, 0.02}, 0.01)),
                                 *findSolidMaterial("steel"));
}

/// σ = −(2π·20 Hz)², as modal analysis uses.
const double kShift = -std::pow(2.0 * std::numbers::pi * 20.0, 2);

TEST(ModalSolve, LanczosFindsWhatTheDenseSolverFinds) {
  // Claim: the 6 rigid and 10 lowest elastic pairs equal those of Eigen's dense generalised
  // solver, with M-orthonormal vectors and small residuals. Reference: dense solver on the same
  // matrices. Tolerances: elastic λ to 1e-8 relative (Lanczos converged to 1e-10 on ν; the dense
  // solver to rounding × condition); rigid λ below 1e-9 of the first elastic one (both solvers
  // leave rounding noise ~ε·λ_max there); orthonormality and residual 1e-8.
  const ElasticMatrices matrices = freeBox();
  ASSERT_GT(matrices.stiffness.rows(), kDenseDofs);
  const int count = kRigidModes + 10;
  const GeneralisedEigenpairs lanczos =
      lowestEigenpairs(matrices.stiffness, matrices.mass, count, kShift);
  const Eigen::MatrixXd stiffness(matrices.stiffness), mass(matrices.mass);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(stiffness, mass);
  ASSERT_EQ(lanczos.eigenvalues.size(), count);
  ASSERT_EQ(lanczos.eigenvectors.cols(), count);
  EXPECT_GT(lanczos.operations, 0);
  const double firstElastic = dense.eigenvalues()[kRigidModes];
  for (int j = 0; j < count; ++j) {
    if (j < kRigidModes) {
      EXPECT_LT(std::abs(lanczos.eigenvalues[j]), 1e-9 * firstElastic) << "pair " << j;
    } else {
      EXPECT_NEAR(lanczos.eigenvalues[j], dense.eigenvalues()[j], 1e-8 * dense.eigenvalues()[j])
          << "pair " << j;
    }
    if (j > 0) {
      EXPECT_LE(lanczos.eigenvalues[j - 1], lanczos.eigenvalues[j]);
    }
  }
  const Eigen::MatrixXd& vectors = lanczos.eigenvectors;
  const Eigen::MatrixXd gram = vectors.transpose() * mass * vectors;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(count, count)).norm(), 1e-8);
  const Eigen::MatrixXd elastic = vectors.rightCols(count - kRigidModes);
  const Eigen::MatrixXd residual =
      stiffness * elastic -
      mass * elastic * lanczos.eigenvalues.tail(count - kRigidModes).asDiagonal();
  EXPECT_LT(residual.norm(), 1e-8 * (stiffness * elastic).norm());
}

TEST(ModalSolve, SameBitsOnEveryRun) {
  // Claim: Spectra's fixed-seed start vector, a sequential reference BLAS and a fixed CHOLMOD
  // ordering give bit-identical pairs. Exact.
  const ElasticMatrices matrices = freeBox();
  const GeneralisedEigenpairs first =
      lowestEigenpairs(matrices.stiffness, matrices.mass, 12, kShift);
  const GeneralisedEigenpairs second =
      lowestEigenpairs(matrices.stiffness, matrices.mass, 12, kShift);
  EXPECT_EQ(first.eigenvalues, second.eigenvalues);
  EXPECT_EQ(first.eigenvectors, second.eigenvectors);
  EXPECT_EQ(first.operations, second.operations);
}

TEST(ModalSolve, SmallSystemsAreSolvedDensely) {
  // Claim: a single free voxel (24 DOFs) gets all its pairs: 6 rigid, 18 elastic, M-orthonormal.
  // Reference: the element's six rigid motions. Tolerance: rounding × condition (1e-9).
  const ElasticMatrices matrices = assembleElasticMatrices(
      hexMesh(voxelBox({0.01, 0.01, 0.01}, 0.01)), *findSolidMaterial("steel"));
  const GeneralisedEigenpairs pairs =
      lowestEigenpairs(matrices.stiffness, matrices.mass, 30, kShift);
  ASSERT_EQ(pairs.eigenvalues.size(), 24);
  for (int j = 0; j < kRigidModes; ++j)
    EXPECT_LT(std::abs(pairs.eigenvalues[j]), 1e-9 * pairs.eigenvalues[kRigidModes]);
  const Eigen::MatrixXd gram =
      pairs.eigenvectors.transpose() * Eigen::MatrixXd(matrices.mass) * pairs.eigenvectors;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(24, 24)).norm(), 1e-9);
}

TEST(ModalSolve, AsksForNearlyEveryPairOfALanczosSizedSystem) {
  // Claim: beyond kDenseDofs, a request for every pair of a 3 × 2 × 2 voxel box (108 DOFs)
  // returns all but the highest (Spectra needs nev < DOFs), equal to the dense solver's.
  // Tolerance: as LanczosFindsWhatTheDenseSolverFinds.
  const ElasticMatrices matrices = assembleElasticMatrices(
      hexMesh(voxelBox({0.03, 0.02, 0.02}, 0.01)), *findSolidMaterial("steel"));
  const Eigen::Index dofs = matrices.stiffness.rows();
  ASSERT_EQ(dofs, 108);
  const GeneralisedEigenpairs pairs =
      lowestEigenpairs(matrices.stiffness, matrices.mass, static_cast<int>(dofs), kShift);
  ASSERT_EQ(pairs.eigenvalues.size(), dofs - 1);
  const Eigen::MatrixXd stiffness(matrices.stiffness), mass(matrices.mass);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(stiffness, mass);
  for (Eigen::Index j = kRigidModes; j < dofs - 1; ++j)
    EXPECT_NEAR(pairs.eigenvalues[j], dense.eigenvalues()[j], 1e-8 * dense.eigenvalues()[j])
        << "pair " << j;
}

TEST(ModalSolve, RefusesAShiftInsideTheSpectrum) {
  // Claim: with σ above the lowest elastic eigenvalue, K − σM is indefinite; CHOLMOD's Cholesky
  // fails and the solve throws rather than fall back to another factorisation.
  const ElasticMatrices matrices = freeBox();
  const GeneralisedEigenpairs pairs =
      lowestEigenpairs(matrices.stiffness, matrices.mass, 8, kShift);
  const double inside = 0.5 * (pairs.eigenvalues[kRigidModes] + pairs.eigenvalues[kRigidModes + 1]);
  EXPECT_THROW(lowestEigenpairs(matrices.stiffness, matrices.mass, 8, inside), std::runtime_error);
}

}  // namespace
}  // namespace fluidsound::acoustics
