// acoustics/modal/hex_element.h — the stiffness and consistent mass of one cubic 8-node voxel
// element of an isotropic elastic solid (modal analysis of sounding solids, shared solids.md §3.2).
// Every element of a voxel solid is the same cube, so these are computed once per solid.
//
// Local node a = dx + 2·dy + 4·dz (dx, dy, dz ∈ {0, 1}) sits at the cube's corner
// origin + h·(dx, dy, dz); local DOF 3a + c is node a's displacement along axis c (x, y, z
// interleaved).
#pragma once

#include <Eigen/Core>

namespace fluidsound::acoustics {

/// A 24 × 24 element matrix in the local DOF order above.
using HexElementMatrix = Eigen::Matrix<double, 24, 24>;

/// @brief The stiffness [N/m] of a cube of edge h, trilinear with Wilson's incompatible modes.
/// @details Each displacement component gets three extra bubble modes (1 − ξ²), (1 − η²), (1 − ζ²)
///          over the natural coordinates ξ, η, ζ ∈ [−1, 1] (Wilson, Taylor, Doherty & Ghaboussi
///          1973; Taylor, Beresford & Wilson 1976). They let the element bend without the
///          parasitic shear that locks plain trilinear hexahedra in thin parts, and are condensed
///          out statically: K = K_cc − K_ci K_ii⁻¹ K_ic. On a cube the Jacobian is constant, so the
///          element passes the patch test without Taylor's correction; 2 × 2 × 2 Gauss points
///          integrate every term exactly.
/// @param edge            h [m], > 0
/// @param youngsModulus   E [Pa], > 0
/// @param poissonsRatio   ν [-], in (−1, 0.5)
/// @note Symmetric, positive semi-definite, with exactly the six rigid motions as its null space.
HexElementMatrix hexElementStiffness(double edge, double youngsModulus, double poissonsRatio);

/// @brief The consistent mass [kg] of a cube of edge h: M_ab = ρ ∫ N_a N_b dV · I₃ over the
///        trilinear shape functions (the incompatible modes carry no mass, as usual).
/// @param edge     h [m], > 0
/// @param density  ρ [kg/m³], > 0
/// @note The entries of each direction sum to the element's mass ρh³.
HexElementMatrix hexElementMass(double edge, double density);

}  // namespace fluidsound::acoustics
