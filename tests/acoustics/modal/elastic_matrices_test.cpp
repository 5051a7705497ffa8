// tests/acoustics/modal/elastic_matrices_test.cpp — the assembled stiffness and mass of a voxel
// solid (elastic_matrices.h): symmetry, the body's mass, rigid motions free of energy, the exact
// energy of uniform stress on a curved solid, and clamping as removal of the nodes' DOFs.
#include "acoustics/modal/elastic_matrices.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

namespace fluidsound::acoustics {
namespace {

/// Rounding of sums of ~100 terms of size ‖K‖: far below any modelling error.
constexpr double kRounding = 1e-12;

SolidMaterial steel() { return *findSolidMaterial("steel"); }

/// A voxel sphere of radius 4 cells: curved, with every kind of surface step.
VoxelSolid smallSphere() {
  const double radius = 0.04;
  return voxelSolidFromInside([&](const Eigen::Vector3d& x) { return x.norm() < radius; },
                              Eigen::Vector3d::Constant(-radius), Eigen::Vector3d::Constant(radius),
                              0.01);
}

/// Node DOFs (x, y, z interleaved) of the displacement field u(position) on `mesh`.
template <typename Field>
Eigen::VectorXd sampled(const HexMesh& mesh, Field displacement) {
  Eigen::VectorXd dofs(3 * static_cast<Eigen::Index>(mesh.positions.size()));
  for (std::size_t n = 0; n < mesh.positions.size(); ++n)
    dofs.segment<3>(3 * static_cast<Eigen::Index>(n)) = displacement(mesh.positions[n]);
  return dofs;
}

TEST(ElasticMatrices, StiffnessAndMassAreSymmetric) {
  // Claim: K and M are sums of symmetric element matrices. Tolerance: rounding.
  const ElasticMatrices matrices = assembleElasticMatrices(hexMesh(smallSphere()), steel());
  const Eigen::SparseMatrix<double> stiffnessAsymmetry =
      matrices.stiffness - Eigen::SparseMatrix<double>(matrices.stiffness.transpose());
  const Eigen::SparseMatrix<double> massAsymmetry =
      matrices.mass - Eigen::SparseMatrix<double>(matrices.mass.transpose());
  EXPECT_LE(stiffnessAsymmetry.norm(), kRounding * matrices.stiffness.norm());
  EXPECT_EQ(massAsymmetry.norm(), 0.0);
}

TEST(ElasticMatrices, TranslationCarriesTheSolidsMass) {
  // Claim: a unit translation along each axis has kinetic mass 1ᵀM1 = ρ·(cells)·h³, the mass of
  // the voxels. Reference: ρV. Tolerance: rounding.
  const VoxelSolid sphere = smallSphere();
  const HexMesh mesh = hexMesh(sphere);
  const ElasticMatrices matrices = assembleElasticMatrices(mesh, steel());
  const double solidMass =
      steel().density * static_cast<double>(sphere.cells.size()) * std::pow(sphere.voxelSize, 3);
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::VectorXd translation =
        sampled(mesh, [&](const Eigen::Vector3d&) { return Eigen::Vector3d::Unit(axis); });
    EXPECT_NEAR(translation.dot(matrices.mass * translation), solidMass, kRounding * solidMass);
  }
}

TEST(ElasticMatrices, RigidMotionsOfTheBodyStoreNoEnergy) {
  // Claim: K·r = 0 for the body's three translations and three rotations (free body).
  // Tolerance: rounding, relative to ‖K‖·‖r‖.
  const HexMesh mesh = hexMesh(smallSphere());
  const ElasticMatrices matrices = assembleElasticMatrices(mesh, steel());
  for (int axis = 0; axis < 3; ++axis) {
    const std::array<Eigen::VectorXd, 2> motions = {
        sampled(mesh, [&](const Eigen::Vector3d&) { return Eigen::Vector3d::Unit(axis); }),
        sampled(mesh, [&](const Eigen::Vector3d& x) {
          return Eigen::Vector3d(Eigen::Vector3d::Unit(axis).cross(x));
        })};
    for (const Eigen::VectorXd& motion : motions)
      EXPECT_LE((matrices.stiffness * motion).norm(),
                kRounding * matrices.stiffness.norm() * motion.norm())
          << "axis " << axis;
  }
}

TEST(ElasticMatrices, UniformStressStoresItsExactEnergyOnACurvedSolid) {
  // Claim (patch test of the assembly): uniaxial stress σ_zz = Eε, u = (−νεx, −νεy, εz), stores
  // ½Eε²·V in any solid, staircase surface included, because every element reproduces the
  // uniform strain exactly. Reference: closed form with V = cells·h³. Tolerance: rounding.
  const VoxelSolid sphere = smallSphere();
  const HexMesh mesh = hexMesh(sphere);
  const SolidMaterial material = steel();
  const ElasticMatrices matrices = assembleElasticMatrices(mesh, material);
  const double strain = 1e-4, nu = material.poissonsRatio;
  const Eigen::VectorXd u = sampled(mesh, [&](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(-nu * strain * x.x(), -nu * strain * x.y(), strain * x.z());
  });
  const double volume = static_cast<double>(sphere.cells.size()) * std::pow(sphere.voxelSize, 3);
  const double expected = 0.5 * material.youngsModulus * strain * strain * volume;
  EXPECT_NEAR(0.5 * u.dot(matrices.stiffness * u), expected, 1e-10 * expected);
}

TEST(ElasticMatrices, ClampingRemovesTheNodesDofs) {
  // Claim: clamping the nodes of the face x = 0 of a 4 × 3 × 2 box removes their 3·12 DOFs; the
  // rest keep their order, and K and M are the unclamped matrices' rows and columns at
  // nodeDofs. Exact.
  const HexMesh mesh = hexMesh(voxelBox({0.04, 0.03, 0.02}, 0.01));
  std::vector<int> clamped;
  for (std::size_t n = 0; n < mesh.gridNodes.size(); ++n)
    if (mesh.gridNodes[n].x() == 0) clamped.push_back(static_cast<int>(n));
  ASSERT_EQ(clamped.size(), 12u);
  const ElasticMatrices free = assembleElasticMatrices(mesh, steel());
  const ElasticMatrices fixed = assembleElasticMatrices(mesh, steel(), clamped);
  const Eigen::Index allDofs = 3 * static_cast<Eigen::Index>(mesh.gridNodes.size());
  EXPECT_EQ(free.stiffness.rows(), allDofs);
  ASSERT_EQ(fixed.stiffness.rows(), allDofs - 36);
  ASSERT_EQ(static_cast<Eigen::Index>(fixed.nodeDofs.size()), allDofs - 36);
  EXPECT_TRUE(std::is_sorted(fixed.nodeDofs.begin(), fixed.nodeDofs.end()));
  const Eigen::MatrixXd freeStiffness(free.stiffness), fixedStiffness(fixed.stiffness);
  const Eigen::MatrixXd freeMass(free.mass), fixedMass(fixed.mass);
  int clampedKept = 0, mismatches = 0;
  for (Eigen::Index i = 0; i < fixedStiffness.rows(); ++i) {
    clampedKept += mesh.gridNodes[fixed.nodeDofs[i] / 3].x() == 0;
    for (Eigen::Index j = 0; j < fixedStiffness.cols(); ++j)
      mismatches += fixedStiffness(i, j) != freeStiffness(fixed.nodeDofs[i], fixed.nodeDofs[j]) ||
                    fixedMass(i, j) != freeMass(fixed.nodeDofs[i], fixed.nodeDofs[j]);
  }
  EXPECT_EQ(clampedKept, 0);
  EXPECT_EQ(mismatches, 0);
}

}  // namespace
}  // namespace fluidsound::acoustics
