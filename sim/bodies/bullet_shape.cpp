// sim/bodies/bullet_shape.cpp — Bullet collision shapes, masses and principal inertias of specs.
#include "sim/bodies/bullet_shape.h"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <LinearMath/btConvexHullComputer.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sim/bodies/body_mass.h"

namespace fluidsound::sim {
namespace {

/// A margin at most this fraction of a body's smallest half size keeps Bullet's inner shape
/// (the body minus its skin) well away from degenerate.
constexpr double kMarginFractionOfSize = 0.1;

[[noreturn]] void reject(const RigidBodySpec& spec, const std::string& what) {
  throw std::invalid_argument("rigid body '" + spec.name + "': " + what);
}

bool positiveFinite(double x) { return x > 0.0 && std::isfinite(x); }

BulletShape sphereShape(const RigidBodySpec& spec, const SphereShape& sphere) {
  if (!positiveFinite(sphere.radius))
    reject(spec, "sphere radius must be finite and > 0 m, got " + std::to_string(sphere.radius));
  BulletShape result;
  result.shape = std::make_unique<btSphereShape>(sphere.radius);
  if (!spec.isStatic) {
    const double r = sphere.radius;
    result.mass = spec.density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
    const double moment = 0.4 * result.mass * r * r;
    result.principalMoments = btVector3(moment, moment, moment);
  }
  return result;
}

BulletShape boxShape(const RigidBodySpec& spec, const BoxShape& box) {
  const Vec3& h = box.halfExtents;
  if (!positiveFinite(h[0]) || !positiveFinite(h[1]) || !positiveFinite(h[2]))
    reject(spec, "box half-extents must be finite and > 0 m");
  BulletShape result;
  auto shape = std::make_unique<btBoxShape>(btVector3(h[0], h[1], h[2]));
  // btBoxShape::setMargin keeps the outer size: the margin is taken from the inside.
  shape->setMargin(
      std::min(kMaxCollisionMargin, kMarginFractionOfSize * std::min({h[0], h[1], h[2]})));
  result.shape = std::move(shape);
  if (!spec.isStatic) {
    result.mass = spec.density * 8.0 * h[0] * h[1] * h[2];
    const double third = result.mass / 3.0;
    result.principalMoments =
        btVector3(third * (h[1] * h[1] + h[2] * h[2]), third * (h[2] * h[2] + h[0] * h[0]),
                  third * (h[0] * h[0] + h[1] * h[1]));
  }
  return result;
}

BulletShape staticMeshShape(const TriangleMesh& mesh) {
  BulletShape result;
  result.vertexCoordinates.reserve(3 * mesh.vertices.size());
  for (const auto& v : mesh.vertices)
    for (int a = 0; a < 3; ++a) result.vertexCoordinates.push_back(v[a]);
  result.triangleIndices.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) result.triangleIndices.push_back(int(t[k]));
  result.triangles = std::make_unique<btTriangleIndexVertexArray>(
      int(mesh.triangles.size()), result.triangleIndices.data(), int(3 * sizeof(int)),
      int(mesh.vertices.size()), result.vertexCoordinates.data(), int(3 * sizeof(btScalar)));
  // Quantized AABB compression: Bullet's recommended BVH for static meshes (less memory, the
  // same contacts: it only culls candidate triangles).
  result.shape = std::make_unique<btBvhTriangleMeshShape>(result.triangles.get(), true);
  return result;
}

BulletShape dynamicMeshShape(const RigidBodySpec& spec, const TriangleMesh& mesh) {
  if (!positiveFinite(spec.density))
    reject(spec, "density must be finite and > 0 kg/m³, got " + std::to_string(spec.density));
  MassProperties mass;
  try {
    mass = meshMassProperties(mesh, spec.density);
  } catch (const std::invalid_argument& e) {
    reject(spec, e.what());
  }
  const PrincipalInertia principal = principalInertia(mass.inertiaAboutCentre);
  const Vec3& c = mass.centreOfMass;
  // Vertices in the body frame: x_body = Rᵀ(x − c), R's columns the principal axes.
  std::vector<double> bodyPoints;
  bodyPoints.reserve(3 * mesh.vertices.size());
  for (const auto& v : mesh.vertices) {
    const Vec3 d{v[0] - c[0], v[1] - c[1], v[2] - c[2]};
    for (int k = 0; k < 3; ++k)
      bodyPoints.push_back(principal.axes[k][0] * d[0] + principal.axes[k][1] * d[1] +
                           principal.axes[k][2] * d[2]);
  }
  btConvexHullComputer hull;
  const double margin =
      hull.compute(bodyPoints.data(), int(3 * sizeof(double)), int(mesh.vertices.size()),
                   kMaxCollisionMargin, kMarginFractionOfSize);
  if (!(margin >= 0.0) || hull.vertices.size() < 4) reject(spec, "the mesh's convex hull is flat");
  auto shape = std::make_unique<btConvexHullShape>();
  for (int i = 0; i < hull.vertices.size(); ++i) shape->addPoint(hull.vertices[i], false);
  shape->recalcLocalAabb();
  shape->setMargin(margin);

  BulletShape result;
  result.shape = std::move(shape);
  result.mass = mass.mass;
  result.principalMoments =
      btVector3(principal.moments[0], principal.moments[1], principal.moments[2]);
  const btMatrix3x3 referenceFromBodyRotation(
      principal.axes[0][0], principal.axes[1][0], principal.axes[2][0],  //
      principal.axes[0][1], principal.axes[1][1], principal.axes[2][1],  //
      principal.axes[0][2], principal.axes[1][2], principal.axes[2][2]);
  result.referenceFromBody = btTransform(referenceFromBodyRotation, btVector3(c[0], c[1], c[2]));
  return result;
}

}  // namespace

BulletShape makeBulletShape(const RigidBodySpec& spec) {
  if (!spec.isStatic && !positiveFinite(spec.density))
    reject(spec, "density must be finite and > 0 kg/m³, got " + std::to_string(spec.density));
  if (const auto* sphere = std::get_if<SphereShape>(&spec.shape)) return sphereShape(spec, *sphere);
  if (const auto* box = std::get_if<BoxShape>(&spec.shape)) return boxShape(spec, *box);
  const auto& mesh = std::get<TriangleMesh>(spec.shape);
  if (mesh.triangles.empty()) reject(spec, "the mesh has no triangles");
  return spec.isStatic ? staticMeshShape(mesh) : dynamicMeshShape(spec, mesh);
}

}  // namespace fluidsound::sim
