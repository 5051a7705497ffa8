// sim/bodies/body_segment.cpp — see body_segment.h.
#include "sim/bodies/body_segment.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "sim/core/quaternion.h"
#include "sim/core/vec3_math.h"

namespace fluidsound::sim {

namespace {

/// Segment p → p + d, t ∈ [0, 1], against the triangle (Möller & Trumbore).
bool crossesTriangle(const Vec3& p, const Vec3& d, const Vec3& v0, const Vec3& v1, const Vec3& v2) {
  const Vec3 e1 = sub(v1, v0), e2 = sub(v2, v0), h = cross(d, e2);
  const double det = dot(e1, h);
  if (std::abs(det) < 1e-30) return false;
  const Vec3 s = sub(p, v0);
  const double u = dot(s, h) / det;
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 q = cross(s, e1);
  const double v = dot(d, q) / det;
  if (v < 0.0 || u + v > 1.0) return false;
  const double t = dot(e2, q) / det;
  return t >= 0.0 && t <= 1.0;
}

/// The triangles of `mesh` the segment p → p + d crosses (stopping at the first when `any`).
std::size_t crossings(const TriangleMesh& mesh, const Vec3& p, const Vec3& d, bool any) {
  const auto vertex = [&mesh](std::uint32_t i) {
    return Vec3{mesh.vertices[i][0], mesh.vertices[i][1], mesh.vertices[i][2]};
  };
  std::size_t count = 0;
  for (const auto& t : mesh.triangles)
    if (crossesTriangle(p, d, vertex(t[0]), vertex(t[1]), vertex(t[2])) && (++count, any)) break;
  return count;
}

}  // namespace

bool segmentCrossesBody(const RigidBodySpec& body, const Vec3& a, const Vec3& b) {
  // In the body's frame: p = R⁻¹(x − position).
  const Quaternion inverse = conjugate(body.rotation);
  const Vec3 p = rotate(inverse, sub(a, body.position)), q = rotate(inverse, sub(b, body.position));
  const Vec3 d = sub(q, p);
  if (const auto* sphere = std::get_if<SphereShape>(&body.shape)) {
    const double dd = dot(d, d);
    const double t = dd > 0.0 ? std::clamp(-dot(p, d) / dd, 0.0, 1.0) : 0.0;
    const Vec3 nearest{p[0] + t * d[0], p[1] + t * d[1], p[2] + t * d[2]};
    return dot(nearest, nearest) <= sphere->radius * sphere->radius;
  }
  if (const auto* box = std::get_if<BoxShape>(&body.shape)) {
    double enter = 0.0, leave = 1.0;  // the slabs' common interval of t
    for (int axis = 0; axis < 3; ++axis) {
      const double h = box->halfExtents[axis];
      if (std::abs(d[axis]) < 1e-300) {
        if (std::abs(p[axis]) > h) return false;
        continue;
      }
      double t0 = (-h - p[axis]) / d[axis], t1 = (h - p[axis]) / d[axis];
      if (t0 > t1) std::swap(t0, t1);
      enter = std::max(enter, t0);
      leave = std::min(leave, t1);
      if (enter > leave) return false;
    }
    return true;
  }
  return crossings(std::get<TriangleMesh>(body.shape), p, d, true) > 0;
}

bool bodyContainsPoint(const RigidBodySpec& body, const Vec3& local) {
  if (const auto* sphere = std::get_if<SphereShape>(&body.shape)) return dot(local, local) <= sphere->radius * sphere->radius;
  if (const auto* box = std::get_if<BoxShape>(&body.shape)) {
    for (int axis = 0; axis < 3; ++axis)
      if (std::abs(local[axis]) > box->halfExtents[axis]) return false;
    return true;
  }
  const Vec3 ray{2.0 * boundingRadius(body) + std::abs(local[0]) + 1.0, 0.0, 0.0};  // beyond the mesh
  return crossings(std::get<TriangleMesh>(body.shape), local, ray, false) % 2 == 1;
}

Vec3 boundingHalfExtents(const RigidBodySpec& body) {
  if (const auto* sphere = std::get_if<SphereShape>(&body.shape)) return {sphere->radius, sphere->radius, sphere->radius};
  if (const auto* box = std::get_if<BoxShape>(&body.shape)) return box->halfExtents;
  Vec3 half{};
  for (const auto& v : std::get<TriangleMesh>(body.shape).vertices)
    for (int a = 0; a < 3; ++a) half[a] = std::max(half[a], std::abs(double(v[a])));
  return half;
}

double boundingRadius(const RigidBodySpec& body) {
  if (const auto* sphere = std::get_if<SphereShape>(&body.shape)) return sphere->radius;
  if (const auto* box = std::get_if<BoxShape>(&body.shape)) return std::sqrt(dot(box->halfExtents, box->halfExtents));
  double largest = 0.0;
  for (const auto& v : std::get<TriangleMesh>(body.shape).vertices)
    largest = std::max(largest, std::sqrt(dot({v[0], v[1], v[2]}, {v[0], v[1], v[2]})));
  return largest;
}

}  // namespace fluidsound::sim
