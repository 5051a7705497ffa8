// tests/acoustics/modal/hex_element_test.cpp — the cube element's stiffness and mass
// (hex_element.h): symmetry, the six rigid motions as its exact null space, the energies of
// uniform stretch and of pure bending, and the mass of the cube (shared solids.md §3.2).
#include "acoustics/modal/hex_element.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace fluidsound::acoustics {
namespace {

// Steel of shared solids.md §4 and a 5 mm voxel: values of the size the solver meets.
constexpr double kYoungsModulus = 2.0e11;  // E [Pa]
constexpr double kPoissonsRatio = 0.29;    // ν [-]
constexpr double kDensity = 7850.0;        // ρ [kg/m³]
constexpr double kEdge = 0.005;            // h [m]

/// Rounding of a sum of ~100 products of entries of size ‖K‖: far below any modelling error.
constexpr double kRounding = 1e-12;

/// Node DOFs of the displacement field u(x) sampled at the cube's corners h·(dx, dy, dz).
template <typename Field>
Eigen::Matrix<double, 24, 1> sampled(Field displacement) {
  Eigen::Matrix<double, 24, 1> dofs;
  for (int a = 0; a < 8; ++a) {
    const Eigen::Vector3d corner = kEdge * Eigen::Vector3d(a & 1, (a >> 1) & 1, (a >> 2) & 1);
    dofs.segment<3>(3 * a) = displacement(corner);
  }
  return dofs;
}

/// The three translations and three rotations (about the cube's centre) as node DOFs.
std::array<Eigen::Matrix<double, 24, 1>, 6> rigidMotions() {
  std::array<Eigen::Matrix<double, 24, 1>, 6> motions;
  const Eigen::Vector3d centre = Eigen::Vector3d::Constant(0.5 * kEdge);
  for (int axis = 0; axis < 3; ++axis) {
    motions[axis] = sampled([&](const Eigen::Vector3d&) { return Eigen::Vector3d::Unit(axis); });
    motions[3 + axis] = sampled([&](const Eigen::Vector3d& x) {
      return Eigen::Vector3d(Eigen::Vector3d::Unit(axis).cross(x - centre));
    });
  }
  return motions;
}

TEST(HexElement, StiffnessIsSymmetric) {
  // Claim: K = ∫BᵀDB dV − K_ci K_ii⁻¹ K_ic is symmetric (D symmetric). Tolerance: rounding.
  const HexElementMatrix stiffness = hexElementStiffness(kEdge, kYoungsModulus, kPoissonsRatio);
  EXPECT_LE((stiffness - stiffness.transpose()).norm(), kRounding * stiffness.norm());
}

TEST(HexElement, RigidMotionsAreTheExactNullSpace) {
  // Claim: translations and rotations strain nothing, K·r = 0 (the bubble modes are not excited
  // by a strain-free field), and nothing else is free: exactly six zero eigenvalues, the seventh
  // positive. Tolerance: rounding relative to ‖K‖‖r‖; the seventh eigenvalue is a physical
  // stiffness, of order E·h / 10, so 1e-3 of the largest marks it as clearly non-zero.
  const HexElementMatrix stiffness = hexElementStiffness(kEdge, kYoungsModulus, kPoissonsRatio);
  for (const Eigen::Matrix<double, 24, 1>& motion : rigidMotions())
    EXPECT_LE((stiffness * motion).norm(), kRounding * stiffness.norm() * motion.norm());
  const Eigen::SelfAdjointEigenSolver<HexElementMatrix> eigen(stiffness);
  const Eigen::Matrix<double, 24, 1> values = eigen.eigenvalues();
  const double largest = values[23];
  for (int j = 0; j < 6; ++j) EXPECT_LE(std::abs(values[j]), kRounding * largest) << "j = " << j;
  EXPECT_GT(values[6], 1e-3 * largest);
}

TEST(HexElement, UniaxialStressStoresHalfEEpsilonSquaredPerVolume) {
  // Claim (patch test): the uniform strain of uniaxial stress σ_xx = Eε — u = (εx, −νεy, −νεz) —
  // stores ½Eε²·h³, which fixes E and ν in D. Reference: closed form. Tolerance: rounding.
  const double strain = 1e-4;
  const HexElementMatrix stiffness = hexElementStiffness(kEdge, kYoungsModulus, kPoissonsRatio);
  const Eigen::Matrix<double, 24, 1> u = sampled([&](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(strain * x.x(), -kPoissonsRatio * strain * x.y(),
                           -kPoissonsRatio * strain * x.z());
  });
  const double energy = 0.5 * u.dot(stiffness * u);
  const double expected = 0.5 * kYoungsModulus * strain * strain * kEdge * kEdge * kEdge;
  EXPECT_NEAR(energy, expected, 1e-10 * expected);
}

TEST(HexElement, PureBendingStoresItsExactEnergyWithoutShearLocking) {
  // Claim: the incompatible modes let the cube bend without parasitic shear. Pure bending about
  // y, σ_xx = Eκz about the cube's mid-plane, has u = κxz, v = −νκyz, w = −κx²/2 + νκ(y² − z²)/2
  // (Timoshenko & Goodier, pure bending of a prism); at the corners w is a constant, so the node
  // DOFs are u and v only, and the bubbles must supply w. The element's energy must equal the
  // exact ∫½Eκ²z² dV = Eκ²h⁵/24. A plain trilinear cube (w = 0 inside) adds the parasitic shears
  // γ_xz = κx, γ_yz = −νκy and misses ε_zz, storing [λ(1−ν)² + 3μ(1+ν²)]/E ≈ 1.53 times as much
  // for ν = 0.29. Reference: closed form. Tolerance: rounding (the field is reproduced exactly).
  const double curvature = 0.1;  // κ [1/m]
  const Eigen::Vector3d centre = Eigen::Vector3d::Constant(0.5 * kEdge);
  const HexElementMatrix stiffness = hexElementStiffness(kEdge, kYoungsModulus, kPoissonsRatio);
  const Eigen::Matrix<double, 24, 1> u = sampled([&](const Eigen::Vector3d& corner) {
    const Eigen::Vector3d x = corner - centre;
    return Eigen::Vector3d(curvature * x.x() * x.z(), -kPoissonsRatio * curvature * x.y() * x.z(),
                           0.0);
  });
  const double energy = 0.5 * u.dot(stiffness * u);
  const double expected = kYoungsModulus * curvature * curvature * std::pow(kEdge, 5) / 24.0;
  EXPECT_NEAR(energy, expected, 1e-10 * expected);
}

TEST(HexElement, StiffnessScalesWithYoungsModulusTimesEdge) {
  // Claim: K ∝ E·h (strain energy ∫ε D ε dV with ε ∝ u/h). Reference: dimensional analysis.
  // Tolerance: rounding.
  const HexElementMatrix base = hexElementStiffness(kEdge, kYoungsModulus, kPoissonsRatio);
  const HexElementMatrix scaled =
      hexElementStiffness(3.0 * kEdge, 2.0 * kYoungsModulus, kPoissonsRatio);
  EXPECT_LE((scaled - 6.0 * base).norm(), kRounding * scaled.norm());
}

TEST(HexElement, MassOfEachDirectionSumsToTheCubesMass) {
  // Claim: the consistent mass moves ρh³ in each direction (row sums: a uniform translation
  // carries the whole cube) and couples no two directions. Reference: ρh³. Tolerance: rounding.
  const HexElementMatrix mass = hexElementMass(kEdge, kDensity);
  const double cubeMass = kDensity * kEdge * kEdge * kEdge;
  for (int c = 0; c < 3; ++c) {
    double total = 0.0;
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) {
        total += mass(3 * a + c, 3 * b + c);
        for (int d = 0; d < 3; ++d)
          if (d != c) {
            EXPECT_EQ(mass(3 * a + c, 3 * b + d), 0.0);
          }
      }
    EXPECT_NEAR(total, cubeMass, kRounding * cubeMass) << "direction " << c;
  }
  EXPECT_EQ((mass - mass.transpose()).norm(), 0.0);
}

TEST(HexElement, MassGivesTheCubesMomentOfInertia) {
  // Claim: the mass is consistent, not lumped: a rotation about an axis through the centre, a
  // linear field interpolated exactly, has kinetic "mass" rᵀMr = ∫ρ(y² + z²)dV = ρh⁵/6 (a lumped
  // mass would give ρh⁵/2, the corners' inertia). Reference: the cube's moment of inertia
  // ρh³·(h² + h²)/12. Tolerance: rounding.
  const HexElementMatrix mass = hexElementMass(kEdge, kDensity);
  const double expected = kDensity * std::pow(kEdge, 5) / 6.0;
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Matrix<double, 24, 1> rotation = rigidMotions()[3 + axis];
    EXPECT_NEAR(rotation.dot(mass * rotation), expected, kRounding * expected) << "axis " << axis;
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
