// sim/bodies/contact_kinematics.h — how two touching bodies move against each other at a
// contact point: closing speed, sliding speed and rolling rate (solids.md §1.4, eqs. 2, 4, 5).
#pragma once

#include "sim/core/vec3.h"

namespace fluidsound::sim {

/// @brief The rigid motion of a body: v(P) = velocity + angularVelocity × (P − centreOfMass).
///        A static body or a wall has zero velocities.
struct BodyMotion {
  Vec3 centreOfMass{};     ///< world [m]
  Vec3 velocity{};         ///< of the centre of mass, world [m/s]
  Vec3 angularVelocity{};  ///< world [rad/s]
};

/// @brief The relative motion at a contact point.
struct ContactKinematics {
  double normalSpeed = 0.0;      ///< (v_B − v_A)·n, > 0 when closing [m/s]
  double tangentialSpeed = 0.0;  ///< ‖tangent-plane part of v_A − v_B‖ [m/s]
  double rollingRate = 0.0;      ///< ‖tangent-plane part of ω_A − ω_B‖ [rad/s]
};

/// @brief Relative motion of A against B at `point` with unit `normal` pointing from B into A:
///        the point velocities vᵢ = v_cm,i + ωᵢ × (point − x_cm,i) (solids.md §1.4), the closing
///        speed (eq. 2, signed so that approach is positive), the sliding speed (eq. 4) and the
///        rolling rate (eq. 5). Eqs. 4 and 5 sum over two orthonormal tangents t1, t2; that is
///        the norm of the tangent-plane projection, which needs no choice of tangents.
/// @param point   world [m]
/// @param normal  unit, world, from B into A
ContactKinematics contactKinematics(const BodyMotion& a, const BodyMotion& b, const Vec3& point,
                                    const Vec3& normal);

}  // namespace fluidsound::sim
