// sim/bodies/bullet_shape.h — the Bullet collision shape, mass and principal inertia of one
// RigidBodySpec, and where Bullet's body frame sits in the spec's frame (rigid-body stage).
#pragma once

#include <btBulletCollisionCommon.h>

#include <memory>
#include <vector>

#include "sim/bodies/rigid_body.h"

namespace fluidsound::sim {

/// @brief Everything Bullet needs to know of a body's shape, owning the memory Bullet reads.
/// @note  Bullet's body frame is the **centre of mass on the principal axes** (btRigidBody
///        takes a diagonal inertia); `referenceFromBody` maps it into the spec's frame (the
///        mesh's own origin and axes, or the centre of a sphere or box).
/// @note  Collision margins (Bullet's rounded skin, used by GJK): a sphere's is its radius; a
///        box keeps its outer size with margin min(kMaxCollisionMargin, 0.1·smallest half
///        extent) inside it; a dynamic mesh's hull is shrunk by min(kMaxCollisionMargin,
///        0.1·inner radius) (btConvexHullComputer) and given that margin, so the hull's faces
///        stay where they were and only its edges and corners are rounded by the margin. A
///        static mesh has none.
struct BulletShape {
  std::vector<btScalar> vertexCoordinates;                ///< static meshes: x, y, z per vertex [m]
  std::vector<int> triangleIndices;                       ///< static meshes: three per triangle
  std::unique_ptr<btTriangleIndexVertexArray> triangles;  ///< static meshes: views the above
  std::unique_ptr<btCollisionShape> shape;
  double mass = 0.0;                    ///< [kg]; 0 for a static body
  btVector3 principalMoments{0, 0, 0};  ///< inertia about the body axes [kg·m²]; 0 if static
  btTransform referenceFromBody = btTransform::getIdentity();  ///< spec frame ← body frame
};

/// Bullet's default margin is 0.04 m, sized for metre-scale game objects; a sounding solid of a
/// few centimetres needs its corners where they are, and double precision keeps GJK accurate
/// with a 1 mm skin.
inline constexpr double kMaxCollisionMargin = 1e-3;  // [m]

/// @brief Builds the shape of `spec` (see BodyShape for the choice per kind), its mass and
///        principal inertia (sim/bodies/body_mass.h for meshes, closed forms otherwise).
/// @throws std::invalid_argument for a non-positive or non-finite size or density (density
///         only for dynamic bodies), an empty mesh, or a mesh enclosing no volume or with a
///         flat hull
BulletShape makeBulletShape(const RigidBodySpec& spec);

}  // namespace fluidsound::sim
