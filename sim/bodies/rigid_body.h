// sim/bodies/rigid_body.h — what the rigid-body stage is told about one sounding solid: its
// shape, material, placement and initial motion (the input record of sim/bodies/rigid_world.h).
#pragma once

#include <string>
#include <variant>

#include "sim/core/quaternion.h"
#include "sim/core/vec3.h"
#include "sim/fluid/triangle_mesh.h"

namespace fluidsound::sim {

/// A solid sphere about its centre.
struct SphereShape {
  double radius = 0.0;  ///< [m], > 0
  bool operator==(const SphereShape&) const = default;
};

/// A solid box about its centre, edges along the body's axes.
struct BoxShape {
  Vec3 halfExtents{};  ///< [m], each > 0
  bool operator==(const BoxShape&) const = default;
};

/// @brief The shape of a body, in the body's own frame.
/// @note A TriangleMesh must be closed and consistently oriented, in metres. How Bullet sees it:
///       - a **dynamic** mesh body collides as the **convex hull** of its vertices (a
///         btConvexHullShape built about the centre of mass, on the principal axes, shrunk by
///         its collision margin so that hull ⊕ margin ≈ the hull: edges and corners rounded by
///         the margin, see sim/bodies/bullet_shape.h); concave parts are filled in;
///       - a **static** mesh body collides as its exact triangles (btBvhTriangleMeshShape);
///       - spheres and boxes are Bullet's btSphereShape and btBoxShape.
///       Mass and inertia: sim/bodies/body_mass.h for meshes (of the mesh, not of its hull),
///       closed forms for spheres (2/5·m·r²) and boxes (m(b² + c²)/3, …).
using BodyShape = std::variant<TriangleMesh, SphereShape, BoxShape>;

/// @brief One rigid body of the scene.
/// @note Material pairs follow Bullet's rules (btManifoldResult): the Coulomb coefficient and
///       the restitution of a contact are the **products** of the two bodies' values (give a
///       floor μ = 1 and e = 1 to let the moving body's own values act). The rolling-resistance
///       arm of a pair is the **sum** of the two bodies' arms (each body's deformation shifts
///       the normal force's line of action; RigidWorld sets it in place of Bullet's product,
///       which would have units of m²). Bullet applies no restitution below an approach speed
///       of RigidWorldSettings::restitutionSpeedThreshold.
struct RigidBodySpec {
  std::string name;         ///< for messages and the contact log's readers
  BodyShape shape;          ///< see BodyShape [m]
  double density = 1000.0;  ///< uniform [kg/m³], > 0; unused for static bodies
  bool isStatic = false;    ///< true: never moves (floors, walls, fixed scenery)
  /// World position of the body's reference point [m]: the mesh's own origin for meshes (not
  /// its centre of mass), the centre for spheres and boxes.
  Vec3 position{};
  Quaternion rotation{};         ///< world-from-body rotation (unit quaternion)
  Vec3 velocity{};               ///< initial velocity of the centre of mass, world [m/s]
  Vec3 angularVelocity{};        ///< initial angular velocity, world [rad/s]
  double friction = 0.5;         ///< Coulomb coefficient μ (≥ 0), combined by product
  double restitution = 0.0;      ///< coefficient of restitution e in [0, 1], by product
  double rollingFriction = 0.0;  ///< rolling-resistance arm δ, M ≤ δ·F_n [m], ≥ 0, by sum
};

}  // namespace fluidsound::sim
