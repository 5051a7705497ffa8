// sim/bodies/body_mass.h — mass properties of a sounding solid: volume, centre of mass and
// inertia tensor of a closed triangle mesh of uniform density, and its principal axes.
#pragma once

#include <array>

#include "sim/core/vec3.h"
#include "sim/fluid/triangle_mesh.h"

namespace fluidsound::sim {

/// A symmetric 3 × 3 tensor as rows (an inertia tensor [kg·m²]).
using InertiaTensor = std::array<Vec3, 3>;

/// @brief What a uniform solid bounded by a closed mesh weighs and how it turns.
struct MassProperties {
  double volume = 0.0;  ///< enclosed volume [m³], > 0
  double mass = 0.0;    ///< density · volume [kg]
  Vec3 centreOfMass{};  ///< in the mesh's own frame [m]
  InertiaTensor
      inertiaAboutCentre{};  ///< I = ∫ρ(|r|²·1 − r rᵀ) dV about centreOfMass, mesh axes [kg·m²]
  bool operator==(const MassProperties&) const = default;
};

/// @brief Volume, centre of mass and inertia tensor of a uniform solid bounded by `mesh`, by
///        the divergence theorem: the volume integrals of 1, x, y, z, x², y², z², xy, yz, zx
///        become sums over the triangles of polynomial surface integrals (Mirtich, "Fast and
///        accurate computation of polyhedral mass properties", J. Graphics Tools 1(2), 1996;
///        in the per-triangle form of Eberly, "Polyhedral Mass Properties (Revisited)",
///        Geometric Tools, 2002). Exact for the mesh up to rounding.
/// @param mesh     closed and consistently oriented [m]; outward or inward alike (an inward
///                 mesh gives a negative signed volume, and every integral is negated)
/// @param density  uniform density [kg/m³], > 0
/// @throws std::invalid_argument if density ≤ 0 or not finite, or the enclosed volume is not
///         positive beyond rounding (open, inconsistently oriented or degenerate mesh)
/// @note Integrates about the centre of the mesh's bounding box, so a mesh far from its
///       origin loses no precision to cancellation.
MassProperties meshMassProperties(const TriangleMesh& mesh, double density);

/// @brief Principal moments and axes of a symmetric tensor: I = R·diag(moments)·Rᵀ, where
///        the columns of R are the principal axes.
struct PrincipalInertia {
  Vec3 moments{};              ///< principal moments of inertia [kg·m²], ascending
  std::array<Vec3, 3> axes{};  ///< unit principal axes (columns of R), right-handed
};

/// @brief Diagonalises a symmetric tensor by cyclic Jacobi rotations (Golub & Van Loan,
///        "Matrix Computations", §8.5), to an off-diagonal norm below 1e-14 of the tensor's
///        norm.
PrincipalInertia principalInertia(const InertiaTensor& inertia);

}  // namespace fluidsound::sim
