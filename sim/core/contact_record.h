// sim/core/contact_record.h — the rigid-body stage's contact log: one record per contact point
// per substep, as logged by sim/bodies/rigid_world.h, and the log with its bodies as written to
// contacts.bin (io/contact_log_file.h) and read for the modal and sample-playback sound
// (solids.md §3.1 and §6 item 2). A stage-boundary record, so it lives in sim/core.
#pragma once

#include <string>
#include <vector>

#include "sim/core/quaternion.h"
#include "sim/core/vec3.h"

namespace fluidsound::sim {

/// @brief A contact point between two bodies (or a body and a wall of the domain) in one
///        substep: where, along which normal, how hard the solver pushed, and how the two
///        surfaces moved against each other there before the solve.
/// @note  Conventions:
///        - Order: bodyA < bodyB for two bodies; a wall is always bodyB.
///        - Geometry (position, normal, local points) is the contact found by the collision
///          detection at the start of the substep, on which the solver acted.
///        - The impulse on A is normalImpulse·normal + frictionImpulse; B receives its
///          opposite. impulse / substep is the mean contact force over the substep [N].
///        - The speeds are measured at `position` from both bodies' velocities at the start of
///          the substep (before gravity, external forces and the solve of this substep).
struct ContactRecord {
  double time = 0.0;  ///< end of the substep [s]
  int bodyA = 0;      ///< index into the specs
  /// index into the specs, or −1 − f for the closed wall on face f of the domain box (f = 0…5
  /// for −x, +x, −y, +y, −z, +z)
  int bodyB = 0;
  Vec3 position{};             ///< world, midway between the two bodies' points [m]
  Vec3 normal{};               ///< unit, world, pointing from B into A
  double normalImpulse = 0.0;  ///< Bullet's applied normal impulse this substep, ≥ 0 [N·s]
  Vec3 frictionImpulse{};      ///< friction impulse on A, in the tangent plane, world [N·s]
  /// closing speed along the normal, > 0 when approaching: (v_B − v_A)·n at the point, with
  /// v = v_cm + ω × (P − x_cm) (solids.md §1.4 eq. 2, with n from B into A) [m/s]
  double normalSpeed = 0.0;
  /// sliding speed ‖(v_A − v_B) − ((v_A − v_B)·n)n‖ at the point (§1.4 eq. 4: the same as
  /// ‖v_t1·t1 + v_t2·t2‖ for any orthonormal tangents) [m/s]
  double tangentialSpeed = 0.0;
  /// ‖(ω_A − ω_B) − ((ω_A − ω_B)·n)n‖, the relative angular velocity in the tangent plane
  /// (§1.4 eq. 5); spin about the normal is excluded [rad/s]
  double rollingRate = 0.0;
  /// Bullet's btManifoldPoint::getLifeTime(): the number of substeps the point has existed in
  /// Bullet's manifold, this one included; **1 means a new contact point** (Bullet refreshes,
  /// and so counts, every point once in the substep that creates it). Bullet may create a
  /// point while the gap is still above RigidWorldSettings::contactDistance (a near miss, not
  /// logged), so the first logged substep of a touch can show 2 or more; and it re-creates
  /// points when a box slides further than its breaking threshold. Decide impacts by
  /// normalSpeed (and the previous substep's log), not by lifetime alone.
  int lifetime = 0;
  Vec3 localPointA{};  ///< A's contact point in A's frame (RigidBodySpec's reference frame) [m]
  Vec3 localPointB{};  ///< B's contact point in B's frame (world frame for a wall) [m]
  /// A's and B's world-from-body rotations at the start of the substep (identity for a wall and
  /// a static body): turn the world-frame impulse and normal into a body's own frame, where its
  /// modes are.
  Quaternion orientationA{};
  Quaternion orientationB{};
  bool operator==(const ContactRecord&) const = default;
};

/// What the contact log says of one body (index = the body's place in the scene's `bodies`).
struct ContactLogBody {
  std::string name;     ///< the scene's name for it
  double mass = 0.0;    ///< [kg]; 0 for a static body
  bool isStatic = false;
  /// The radius of curvature a Hertz contact with this body sees [m], > 0: a sphere's radius, else
  /// half the smallest side of its bounding box (a choice: docs/solids.md, Impacts).
  double contactRadius = 0.0;
  bool operator==(const ContactLogBody&) const = default;
};

/// The whole contact log of a run (contacts.bin, `fluidsound.contacts/1`).
struct ContactLog {
  double substep = 1e-3;               ///< the rigid-body substep [s]
  double duration = 0.0;               ///< simulated time [s]
  std::vector<ContactLogBody> bodies;  ///< one per scene body, in order
  std::vector<ContactRecord> records;  ///< in time order; within a substep by (bodyA, bodyB)
  bool operator==(const ContactLog&) const = default;
};

}  // namespace fluidsound::sim
