// tests/sim/bodies/body_mass_test.cpp — mass properties of closed meshes (divergence theorem)
// against closed forms: a box (offset, rotated, far from the origin, inward-oriented), an
// icosphere against an independent tetrahedral decomposition and the sphere it approximates,
// and the principal axes of a rotated box.
#include "sim/bodies/body_mass.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sim/core/quaternion.h"
#include "support/body_test_meshes.h"

namespace fluidsound::sim {
namespace {

/// The box's corners are exact in float and every integral is a short sum of exact products,
/// so the results carry only double rounding: a few ulps of the largest term. 1e-12 relative
/// leaves a factor of ~1000 for summation order.
constexpr double kRoundingTolerance = 1e-12;

double maxAbs(const InertiaTensor& t) {
  double m = 0.0;
  for (const Vec3& row : t)
    for (const double e : row) m = std::max(m, std::abs(e));
  return m;
}

TEST(MeshMassProperties, BoxMatchesClosedForm) {
  // Claim: a box of half-extents (a, b, c) has V = 8abc, its centre as centre of mass and
  // I = diag(m(b²+c²)/3, m(c²+a²)/3, m(a²+b²)/3) about it (any mechanics text). Reference:
  // these closed forms. Tolerance: rounding only (kRoundingTolerance).
  const Vec3 half{0.125, 0.25, 0.5};
  const Vec3 centre{1.0, 2.0, -3.0};
  const double density = 7850.0;
  const MassProperties p = meshMassProperties(
      test::boxMesh({centre[0] - half[0], centre[1] - half[1], centre[2] - half[2]},
                    {centre[0] + half[0], centre[1] + half[1], centre[2] + half[2]}),
      density);
  const double volume = 8.0 * half[0] * half[1] * half[2];
  const double mass = density * volume;
  EXPECT_NEAR(p.volume, volume, kRoundingTolerance * volume);
  EXPECT_NEAR(p.mass, mass, kRoundingTolerance * mass);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(p.centreOfMass[a], centre[a], kRoundingTolerance);
  const Vec3 diagonal{mass * (half[1] * half[1] + half[2] * half[2]) / 3.0,
                      mass * (half[2] * half[2] + half[0] * half[0]) / 3.0,
                      mass * (half[0] * half[0] + half[1] * half[1]) / 3.0};
  const double scale = maxAbs(p.inertiaAboutCentre);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(p.inertiaAboutCentre[i][j], i == j ? diagonal[i] : 0.0,
                  kRoundingTolerance * scale)
          << "I[" << i << "][" << j << "]";
}

TEST(MeshMassProperties, TetrahedronProductsOfInertiaMatchClosedForm) {
  // Claim: the products of inertia (off-diagonal entries, sign included) are right. Reference:
  // the tetrahedron (0, 0, 0), (1, 0, 0), (0, 2, 0), (0, 0, 3) of unit density has V = 1,
  // centre (1/4, 1/2, 3/4) and, from ∫xᵢxⱼ dV = V/20·(Σₖ pₖᵢpₖⱼ + (Σₖ pₖᵢ)(Σₖ pₖⱼ)) (Tonon,
  // J. Math. Stat. 1(1), 2004) and the parallel-axis theorem, the covariance about the centre
  // C = [[0.0375, −0.025, −0.0375], [−0.025, 0.15, −0.075], [−0.0375, −0.075, 0.3375]], so
  // I = tr(C)·1 − C = [[0.4875, 0.025, 0.0375], [0.025, 0.375, 0.075], [0.0375, 0.075, 0.1875]].
  // Tolerance: rounding only.
  TriangleMesh tetrahedron;
  tetrahedron.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
  tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const MassProperties p = meshMassProperties(tetrahedron, 1.0);
  EXPECT_NEAR(p.volume, 1.0, kRoundingTolerance);
  const Vec3 centre{0.25, 0.5, 0.75};
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(p.centreOfMass[a], centre[a], kRoundingTolerance);
  const InertiaTensor reference{Vec3{0.4875, 0.025, 0.0375}, Vec3{0.025, 0.375, 0.075},
                                Vec3{0.0375, 0.075, 0.1875}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(p.inertiaAboutCentre[i][j], reference[i][j], kRoundingTolerance)
          << "I[" << i << "][" << j << "]";
}

TEST(MeshMassProperties, FarFromOriginKeepsPrecision) {
  // Claim: integrating about the bounding box's centre keeps full precision for a body 1 km
  // from its file's origin. Reference: the closed form of the box test (corners exact in
  // float: 1000 ± 0.125). Tolerance: rounding only; without the shift the second moments
  // would cancel ~(1000/0.125)² ≈ 6e7 of their digits and miss 1e-12 by far.
  const MassProperties p = meshMassProperties(
      test::boxMesh({999.875, 999.875, 999.875}, {1000.125, 1000.125, 1000.125}), 1.0);
  const double volume = 0.25 * 0.25 * 0.25;
  const double moment = volume * (2.0 * 0.125 * 0.125) / 3.0;
  EXPECT_NEAR(p.volume, volume, kRoundingTolerance * volume);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(p.centreOfMass[a], 1000.0, kRoundingTolerance * 1000.0);
    EXPECT_NEAR(p.inertiaAboutCentre[a][a], moment, kRoundingTolerance * moment);
  }
}

TEST(MeshMassProperties, InwardOrientationGivesTheSameSolid) {
  // Claim: reversing every triangle (an inward mesh) describes the same solid. Reference: the
  // outward mesh's result. Tolerance: exact, every integral is only negated twice.
  TriangleMesh mesh = test::boxMesh({0.0, 0.0, 0.0}, {0.5, 0.25, 1.0});
  const MassProperties outward = meshMassProperties(mesh, 1000.0);
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  EXPECT_EQ(meshMassProperties(mesh, 1000.0), outward);
}

TEST(MeshMassProperties, RejectsOpenMeshAndBadDensity) {
  // Claim: a mesh that encloses nothing (a single square) and a non-positive density are
  // refused with std::invalid_argument.
  TriangleMesh square;
  square.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_THROW(meshMassProperties(square, 1000.0), std::invalid_argument);
  EXPECT_THROW(meshMassProperties(test::boxMesh({0, 0, 0}, {1, 1, 1}), 0.0), std::invalid_argument);
}

TEST(MeshMassProperties, IcosphereMatchesTetrahedraAndSphere) {
  // Claim 1: for a star-shaped polyhedron about the origin, the volume and second moments
  // equal the sums over the tetrahedra (0, p₀, p₁, p₂): V = det/6 and
  // ∫xᵢxⱼ dV = V/20·(Σₖ pₖᵢpₖⱼ + (Σₖ pₖᵢ)(Σₖ pₖⱼ)) (the covariance of a tetrahedron, e.g.
  // Tonon, J. Math. Stat. 1(1), 2004) — an independent closed form. Tolerance: rounding over
  // 1280 triangles, kRoundingTolerance × 10.
  const double radius = 0.05;
  const double density = 2700.0;
  const TriangleMesh mesh = test::icosphereMesh(radius, 3);
  const MassProperties p = meshMassProperties(mesh, density);
  double volume = 0.0;
  InertiaTensor second{};  // ∫xᵢxⱼ dV about the origin
  double longestEdge = 0.0;
  for (const auto& t : mesh.triangles) {
    std::array<Vec3, 3> q{};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) q[k][a] = mesh.vertices[t[k]][a];
    const double det = q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) -
                       q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
                       q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
    const double v = det / 6.0;
    volume += v;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double products = 0.0;
        for (int k = 0; k < 3; ++k) products += q[k][i] * q[k][j];
        second[i][j] +=
            v / 20.0 * (products + (q[0][i] + q[1][i] + q[2][i]) * (q[0][j] + q[1][j] + q[2][j]));
      }
    for (int k = 0; k < 3; ++k) {
      const Vec3& a = q[k];
      const Vec3& b = q[(k + 1) % 3];
      longestEdge = std::max(longestEdge, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    }
  }
  const double tight = 10.0 * kRoundingTolerance;
  EXPECT_NEAR(p.volume, volume, tight * volume);
  // The icosphere is symmetric about the origin up to float rounding of its vertices
  // (2⁻²⁴·r), so its centre of mass lies within that of the origin.
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(p.centreOfMass[a], 0.0, 1e-7 * radius);
  const double trace = second[0][0] + second[1][1] + second[2][2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double reference = density * ((i == j ? trace : 0.0) - second[i][j]);
      // Moments about the centre differ from those about the origin by m·|c|², c ≲ 1e-7·r.
      EXPECT_NEAR(p.inertiaAboutCentre[i][j], reference, tight * density * trace)
          << "I[" << i << "][" << j << "]";
    }

  // Claim 2: it approaches the sphere it is inscribed in: V → 4πr³/3 and I → (2/5)·m·r²·1.
  // Reference: those closed forms. Tolerance: every face lies within its sagitta s ≤ ℓ²/(6r)
  // of the sphere (circumradius ℓ/√3 of a face with longest edge ℓ), so the volume deficit is
  // at most 3s/r and the moment (∝ m·r_eff²) at most 2s/r below (2/5)·m·r².
  const double sagittaRatio = longestEdge * longestEdge / (6.0 * radius * radius);
  const double sphereVolume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  EXPECT_LT(p.volume, sphereVolume);
  EXPECT_GT(p.volume, (1.0 - 3.0 * sagittaRatio) * sphereVolume);
  const double sphereMoment = 0.4 * p.mass * radius * radius;
  for (int a = 0; a < 3; ++a) {
    EXPECT_LT(p.inertiaAboutCentre[a][a], sphereMoment);
    EXPECT_GT(p.inertiaAboutCentre[a][a], (1.0 - 2.0 * sagittaRatio) * sphereMoment);
  }
}

TEST(PrincipalInertia, RecoversMomentsAndAxesOfARotatedBox) {
  // Claim: for I = R·diag(d)·Rᵀ, principalInertia returns d (ascending) and R's columns up to
  // sign, right-handed. Reference: the constructed R and d. Tolerance: Jacobi stops at
  // off-diagonals below 1e-14·‖I‖; eigenvalue errors are of that order, eigenvector errors
  // of that over the smallest gap (here (2 − 1)/3 of ‖I‖), so 1e-12 with margin.
  const Vec3 d{1.0, 2.0, 3.0};
  const Quaternion q = quaternionFromAxisAngle({1.0, 2.0, 3.0}, 0.7);
  std::array<Vec3, 3> columns{rotate(q, {1, 0, 0}), rotate(q, {0, 1, 0}), rotate(q, {0, 0, 1})};
  InertiaTensor inertia{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) inertia[i][j] += columns[k][i] * d[k] * columns[k][j];
  const PrincipalInertia p = principalInertia(inertia);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(p.moments[k], d[k], 1e-12);
    const double dot =
        p.axes[k][0] * columns[k][0] + p.axes[k][1] * columns[k][1] + p.axes[k][2] * columns[k][2];
    EXPECT_NEAR(std::abs(dot), 1.0, 1e-12) << "axis " << k;
  }
  const Vec3& a = p.axes[0];
  const Vec3& b = p.axes[1];
  const Vec3& c = p.axes[2];
  const double handedness = c[0] * (a[1] * b[2] - a[2] * b[1]) +
                            c[1] * (a[2] * b[0] - a[0] * b[2]) + c[2] * (a[0] * b[1] - a[1] * b[0]);
  EXPECT_NEAR(handedness, 1.0, 1e-12);
}

}  // namespace
}  // namespace fluidsound::sim
