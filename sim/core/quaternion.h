// sim/core/quaternion.h — the orientation of a rigid body as a unit quaternion (the rotation
// from the body's frame to world space), with the few operations the bodies stage needs.
#pragma once

#include <cmath>

#include "sim/core/vec3.h"

namespace fluidsound::sim {

/// @brief A rotation as the unit quaternion q = w + x·i + y·j + z·k (Hamilton convention, as
///        Bullet's btQuaternion): rotate(q, v) = q·v·q*. The default is the identity.
struct Quaternion {
  double w = 1.0;
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  bool operator==(const Quaternion&) const = default;
};

/// @brief The rotation by `angle` [rad] about `axis` (right-hand rule; any length > 0).
/// @return the identity if `axis` is the zero vector
inline Quaternion quaternionFromAxisAngle(const Vec3& axis, double angle) {
  const double length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (length == 0.0) return {};
  const double s = std::sin(0.5 * angle) / length;
  return {std::cos(0.5 * angle), s * axis[0], s * axis[1], s * axis[2]};
}

/// @return the product a·b: the rotation b followed by a
inline Quaternion operator*(const Quaternion& a, const Quaternion& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

/// @return the inverse rotation of a unit quaternion
inline Quaternion conjugate(const Quaternion& q) { return {q.w, -q.x, -q.y, -q.z}; }

/// @return v turned by the unit quaternion q
inline Vec3 rotate(const Quaternion& q, const Vec3& v) {
  // v + 2w(u × v) + 2u × (u × v) with u = (x, y, z): q·v·q* expanded for a unit q.
  const Vec3 u{q.x, q.y, q.z};
  const Vec3 t{2.0 * (u[1] * v[2] - u[2] * v[1]), 2.0 * (u[2] * v[0] - u[0] * v[2]),
               2.0 * (u[0] * v[1] - u[1] * v[0])};
  return {v[0] + q.w * t[0] + (u[1] * t[2] - u[2] * t[1]),
          v[1] + q.w * t[1] + (u[2] * t[0] - u[0] * t[2]),
          v[2] + q.w * t[2] + (u[0] * t[1] - u[1] * t[0])};
}

}  // namespace fluidsound::sim
