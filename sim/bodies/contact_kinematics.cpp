// sim/bodies/contact_kinematics.cpp — relative motion at a contact point (solids.md §1.4).
#include "sim/bodies/contact_kinematics.h"

#include <cmath>

namespace fluidsound::sim {
namespace {

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 pointVelocity(const BodyMotion& body, const Vec3& point) {
  const Vec3 arm{point[0] - body.centreOfMass[0], point[1] - body.centreOfMass[1],
                 point[2] - body.centreOfMass[2]};
  const Vec3 turning = cross(body.angularVelocity, arm);
  return {body.velocity[0] + turning[0], body.velocity[1] + turning[1],
          body.velocity[2] + turning[2]};
}

/// ‖u − (u·n)n‖ for a unit n.
double tangentialNorm(const Vec3& u, const Vec3& n) {
  const double along = dot(u, n);
  const Vec3 t{u[0] - along * n[0], u[1] - along * n[1], u[2] - along * n[2]};
  return std::sqrt(dot(t, t));
}

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
