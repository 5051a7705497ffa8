// sim/bodies/body_mass.cpp — mass properties of a closed triangle mesh (divergence theorem) and
// principal axes of an inertia tensor (cyclic Jacobi).
#include "sim/bodies/body_mass.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace fluidsound::sim {
namespace {

/// A volume this small relative to the bounding box's (largest extent)³ is rounding, not a
/// solid: a double sum over n triangles carries a relative error ≈ n·2⁻⁵³ ≈ 1e-10 even for a
/// million triangles, far below this.
constexpr double kDegenerateVolumeFraction = 1e-9;

/// Sums of the monomials of one coordinate over a triangle's three corners w0, w1, w2 (Eberly
/// 2002, "Subexpressions"): f1 = Σwᵢ, f2 = Σ_{i≤j} wᵢwⱼ, f3 = Σ_{i≤j≤k} wᵢwⱼwₖ, and
/// gᵢ = f2 + wᵢ(f1 + wᵢ), the weights of the mixed products.
struct CornerSums {
  double f1, f2, f3, g0, g1, g2;
};

CornerSums cornerSums(double w0, double w1, double w2) {
  const double sum01 = w0 + w1;
  const double f1 = sum01 + w2;
  const double square0 = w0 * w0;
  const double quadratic01 = square0 + w1 * sum01;
  const double f2 = quadratic01 + w2 * f1;
  const double f3 = w0 * square0 + w1 * quadratic01 + w2 * f2;
  return {f1, f2, f3, f2 + w0 * (f1 + w0), f2 + w1 * (f1 + w1), f2 + w2 * (f1 + w2)};
}

}  // namespace

MassProperties meshMassProperties(const TriangleMesh& mesh, double density) {
  if (!(density > 0.0) || !std::isfinite(density))
    throw std::invalid_argument("meshMassProperties: density must be finite and > 0 (kg/m³), got " +
                                std::to_string(density));
  // Integrate about the bounding box's centre c: the integrals are then of the size of the body,
  // not of its distance from the file's origin.
  Vec3 lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -std::numeric_limits<double>::infinity();
  }
  for (const auto& triangle : mesh.triangles)
    for (const std::uint32_t index : triangle)
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], double(mesh.vertices[index][a]));
        hi[a] = std::max(hi[a], double(mesh.vertices[index][a]));
      }
  Vec3 c{};
  double extent = 0.0;
  for (int a = 0; a < 3; ++a) {
    c[a] = 0.5 * (lo[a] + hi[a]);
    extent = std::max(extent, hi[a] - lo[a]);
  }

  // ∫1, ∫x, ∫y, ∫z, ∫x², ∫y², ∫z², ∫xy, ∫yz, ∫zx over the volume (about c), each as Σ over the
  // triangles of (edge₁ × edge₂)ₐ times a corner sum (Eberly 2002, eq. for "intg").
  std::array<double, 10> integral{};
  for (const auto& triangle : mesh.triangles) {
    std::array<Vec3, 3> p{};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) p[k][a] = double(mesh.vertices[triangle[k]][a]) - c[a];
    const Vec3 e1{p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const Vec3 e2{p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const Vec3 d{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                 e1[0] * e2[1] - e1[1] * e2[0]};
    const CornerSums x = cornerSums(p[0][0], p[1][0], p[2][0]);
    const CornerSums y = cornerSums(p[0][1], p[1][1], p[2][1]);
    const CornerSums z = cornerSums(p[0][2], p[1][2], p[2][2]);
    integral[0] += d[0] * x.f1;
    integral[1] += d[0] * x.f2;
    integral[2] += d[1] * y.f2;
    integral[3] += d[2] * z.f2;
    integral[4] += d[0] * x.f3;
    integral[5] += d[1] * y.f3;
    integral[6] += d[2] * z.f3;
    integral[7] += d[0] * (p[0][1] * x.g0 + p[1][1] * x.g1 + p[2][1] * x.g2);
    integral[8] += d[1] * (p[0][2] * y.g0 + p[1][2] * y.g1 + p[2][2] * y.g2);
    integral[9] += d[2] * (p[0][0] * z.g0 + p[1][0] * z.g1 + p[2][0] * z.g2);
  }
  constexpr std::array<double, 10> kWeight{1.0 / 6.0,   1.0 / 24.0, 1.0 / 24.0, 1.0 / 24.0,
                                           1.0 / 60.0,  1.0 / 60.0, 1.0 / 60.0, 1.0 / 120.0,
                                           1.0 / 120.0, 1.0 / 120.0};
  // An inward-oriented mesh has every surface normal, hence every integral, negated.
  const double orientation = integral[0] < 0.0 ? -1.0 : 1.0;
  for (int k = 0; k < 10; ++k) integral[k] *= orientation * kWeight[k];

  const double volume = integral[0];
  if (!(volume > kDegenerateVolumeFraction * extent * extent * extent))
    throw std::invalid_argument(
        "meshMassProperties: the mesh encloses no volume (open, inconsistently oriented or "
        "degenerate): volume " +
        std::to_string(volume) + " m³ for a bounding box of " + std::to_string(extent) + " m");

  const Vec3 centre{integral[1] / volume, integral[2] / volume, integral[3] / volume};
  // Second moments about the centre of mass (parallel-axis theorem), per unit density.
  const double xx = integral[4] - volume * centre[0] * centre[0];
  const double yy = integral[5] - volume * centre[1] * centre[1];
  const double zz = integral[6] - volume * centre[2] * centre[2];
  const double xy = integral[7] - volume * centre[0] * centre[1];
  const double yz = integral[8] - volume * centre[1] * centre[2];
  const double zx = integral[9] - volume * centre[2] * centre[0];

  MassProperties result;
  result.volume = volume;
  result.mass = density * volume;
  result.centreOfMass = {centre[0] + c[0], centre[1] + c[1], centre[2] + c[2]};
  result.inertiaAboutCentre = {Vec3{density * (yy + zz), -density * xy, -density * zx},
                               Vec3{-density * xy, density * (zz + xx), -density * yz},
                               Vec3{-density * zx, -density * yz, density * (xx + yy)}};
  return result;
}

PrincipalInertia principalInertia(const InertiaTensor& inertia) {
  InertiaTensor a = inertia;
  InertiaTensor v{Vec3{1.0, 0.0, 0.0}, Vec3{0.0, 1.0, 0.0}, Vec3{0.0, 0.0, 1.0}};
  double norm2 = 0.0;
  for (const Vec3& row : a)
    for (const double entry : row) norm2 += entry * entry;
  constexpr double kOffDiagonalTolerance = 1e-14;  ///< relative to ‖I‖; ~50 ulps of double
  constexpr int kMaxSweeps = 50;                   ///< Jacobi converges quadratically, in < 10
  constexpr std::array<std::pair<int, int>, 3> kPairs{{{0, 1}, {0, 2}, {1, 2}}};
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    const double off2 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (off2 <= kOffDiagonalTolerance * kOffDiagonalTolerance * norm2) break;
    for (const auto& [p, q] : kPairs) {
      if (a[p][q] == 0.0) continue;
      // The rotation J in the (p, q) plane that zeroes a[p][q] in Jᵀ·A·J (Golub & Van Loan,
      // Algorithm 8.5.1, the smaller of the two angles).
      const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
      const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::hypot(theta, 1.0));
      const double cosine = 1.0 / std::hypot(t, 1.0);
      const double sine = t * cosine;
      for (int k = 0; k < 3; ++k) {  // A·J: columns p and q
        const double akp = a[k][p], akq = a[k][q];
        a[k][p] = cosine * akp - sine * akq;
        a[k][q] = sine * akp + cosine * akq;
      }
      for (int k = 0; k < 3; ++k) {  // Jᵀ·(A·J): rows p and q
        const double apk = a[p][k], aqk = a[q][k];
        a[p][k] = cosine * apk - sine * aqk;
        a[q][k] = sine * apk + cosine * aqk;
      }
      for (int k = 0; k < 3; ++k) {  // V·J accumulates the eigenvectors as columns
        const double vkp = v[k][p], vkq = v[k][q];
        v[k][p] = cosine * vkp - sine * vkq;
        v[k][q] = sine * vkp + cosine * vkq;
      }
    }
  }
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return a[i][i] < a[j][j]; });
  PrincipalInertia result;
  for (int k = 0; k < 3; ++k) {
    result.moments[k] = a[order[k]][order[k]];
    result.axes[k] = {v[0][order[k]], v[1][order[k]], v[2][order[k]]};
  }
  // Right-handed: axes[2] = axes[0] × axes[1].
  const Vec3& e0 = result.axes[0];
  const Vec3& e1 = result.axes[1];
  result.axes[2] = {e0[1] * e1[2] - e0[2] * e1[1], e0[2] * e1[0] - e0[0] * e1[2],
                    e0[0] * e1[1] - e0[1] * e1[0]};
  return result;
}

}  // namespace fluidsound::sim
