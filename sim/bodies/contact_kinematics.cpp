// sim/bodies/contact_kinematics.cpp — relative motion at a contact point (solids.md §1.4).
#include "sim/bodies/contact_kinematics.h"

#include "sim/core/vec3_math.h"

#include <cmath>

namespace fluidsound::sim {
namespace {

Vec3 pointVelocity(const BodyMotion& body, const Vec3& point) {
  return add(body.velocity, cross(body.angularVelocity, sub(point, body.centreOfMass)));
}

/// ‖u − (u·n)n‖ for a unit n.
double tangentialNorm(const Vec3& u, const Vec3& n) { return norm(sub(u, scaled(n, dot(u, n)))); }

}  // namespace

ContactKinematics contactKinematics(const BodyMotion& a, const BodyMotion& b, const Vec3& point,
                                    const Vec3& normal) {
  const Vec3 va = pointVelocity(a, point);
  const Vec3 vb = pointVelocity(b, point);
  const Vec3 slip{va[0] - vb[0], va[1] - vb[1], va[2] - vb[2]};
  const Vec3 spin{a.angularVelocity[0] - b.angularVelocity[0],
                  a.angularVelocity[1] - b.angularVelocity[1],
                  a.angularVelocity[2] - b.angularVelocity[2]};
  return {-dot(slip, normal), tangentialNorm(slip, normal), tangentialNorm(spin, normal)};
}

}  // namespace fluidsound::sim
