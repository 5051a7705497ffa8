// sim/bodies/rigid_world.h — rigid-body stage: Bullet 3.24 dynamics of the sounding solids at a
// fixed substep, logging every contact point of every substep (solids.md §3.1, §6 item 2).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "sim/core/contact_record.h"
#include "sim/bodies/domain_walls.h"
#include "sim/core/quaternion.h"
#include "sim/bodies/rigid_body.h"
#include "sim/core/vec3.h"

namespace fluidsound::sim {

/// The longest substep the stage accepts [s]: contact impulses are turned into force pulses
/// per substep, and solids.md §3.1 asks for 1 ms or finer.
inline constexpr double kMaxRigidSubstep = 1e-3;

/// @brief How the rigid-body world steps and what it counts as a contact.
struct RigidWorldSettings {
  Vec3 gravity{0.0, -9.81, 0.0};    ///< [m/s²]
  double substep = 1e-3;            ///< fixed step [s], 0 < substep ≤ kMaxRigidSubstep
  std::optional<DomainBox> domain;  ///< closed faces become static walls (domain_walls.h)
  /// @brief The largest gap at which a contact point is solved and logged [m], ≥ 0.
  /// @details Bullet keeps manifold points up to its contact breaking threshold (2 % of a
  ///          shape's bounding radius) apart and, by default, solves them all as speculative
  ///          contacts: a point with gap d gets the impulse that closes the gap within the
  ///          substep, so an impact found d early loses m·d/substep of its impulse (measured:
  ///          6.6 % for a 1 cm ball at 2 m/s found 0.2 mm early; up to 12 % at its 0.35 mm
  ///          breaking threshold). This threshold, set as every object's contact
  ///          processing threshold, caps that loss at m·contactDistance/substep (1 mm/s of
  ///          approach speed at 1 µm and 1 ms, 0.03 % of a 0.2 m drop's impulse), while a
  ///          resting contact, whose gap the solver holds at 0 to rounding (≈ 1e-15 m), stays
  ///          solved and logged in every substep.
  double contactDistance = 1e-6;
  /// Approach speed below which Bullet applies no restitution [m/s] (Bullet's default,
  /// btContactSolverInfo::m_restitutionVelocityThreshold): ends a settling body's ever
  /// smaller bounces (a 0.2 m/s impact follows a 2 mm drop). Impacts below it are still
  /// solved and logged, inelastically.
  double restitutionSpeedThreshold = 0.2;
  int solverIterations = 10;  ///< sequential-impulse iterations per substep (Bullet's default)
};

/// @brief Where a body is: its reference point (RigidBodySpec::position) and orientation.
struct BodyPose {
  Vec3 position{};           ///< world [m]
  Quaternion orientation{};  ///< world-from-body
};

/// @brief How a body moves.
struct BodyVelocity {
  Vec3 linear{};   ///< of the centre of mass, world [m/s]
  Vec3 angular{};  ///< world [rad/s]
};

/// @brief The rigid bodies of a scene in a Bullet btDiscreteDynamicsWorld (default collision
///        configuration, btCollisionDispatcher, btDbvtBroadphase, sequential-impulse solver
///        with two friction directions per contact), stepped at a fixed substep, with a log
///        of every contact point of every substep.
/// @details Each substep: (1) every body's centre of mass and velocities are stored; (2) the
///          external forces are applied; (3) stepSimulation(substep, 1, substep) takes one
///          internal step; (4) every manifold point with gap ≤ contactDistance (exactly the
///          points the solver acted on) is appended to the log, with the speeds measured from
///          the velocities stored in (1) and Bullet's applied impulses of the solve. Records of
///          one substep are ordered by (bodyA, bodyB), then Bullet's point order.
/// @note  Solver: Bullet's defaults (10 iterations, warm starting 0.85, erp2 0.2) except two
///        friction directions per point, and split impulse for every penetration (Bullet's
///        default splits only beyond 4 cm): the push-out of a penetration is done with
///        pseudo-velocities and never enters the logged impulse.
/// @note  Friction per point is a pyramid: Bullet clamps each of the two directions to μ·J_n
///        separately, so one sliding point can log up to √2·μ·J_n; sums over a body's points
///        and a few substeps are Coulomb's (rigid_world_test: within 0.03 %). A sliding box's
///        manifold also drops and re-adds points (Bullet's breaking threshold is 2 % of the
///        shape's size), so its per-substep normal impulses fluctuate about the mean.
/// @note  Deterministic: the same specs and settings give a bit-identical log (single-threaded
///        Bullet, bodies inserted in spec order, walls after them, no randomised solver order,
///        no deactivation). No state outside the object: no Bullet global is written and no
///        Bullet callback is installed (Bullet itself reads its default contact breaking
///        threshold, gContactBreakingThreshold = 0.02, which nothing here changes).
/// @note  Bodies never sleep (Bullet's deactivation would freeze impulses). Continuous
///        collision detection is off: a body should move less than about its smallest half
///        size per substep (10 m/s for a 1 cm ball at 1 ms). Bullet limits a body's rotation to
///        π/4 per substep (785 rad/s at 1 ms). A static triangle mesh can give small normal
///        kicks where a body slides over its internal edges (Bullet's internal-edge
///        correction needs a global callback and is not used).
/// @par Example
/// @code
///   RigidWorld world({floor, ball});   // specs; gravity −9.81 m/s² along y, 1 ms substeps
///   world.advance(0.5);                // 500 substeps
///   for (const ContactRecord& c : world.contacts())
///     if (c.normalSpeed > 0.02) { /* closing faster than solids.md §1.4's impact threshold */ }
/// @endcode
class RigidWorld {
 public:
  /// @throws std::invalid_argument for settings out of range (naming the field) or a body
  ///         that makes no sense (naming the body: size, density, μ < 0, e outside [0, 1],
  ///         δ < 0, non-finite placement or motion, a rotation that is not a unit quaternion
  ///         to 1e-6), or a domain box with max ≤ min
  explicit RigidWorld(std::vector<RigidBodySpec> bodies, const RigidWorldSettings& settings = {});
  ~RigidWorld();
  RigidWorld(RigidWorld&&) noexcept;
  RigidWorld& operator=(RigidWorld&&) noexcept;
  RigidWorld(const RigidWorld&) = delete;
  RigidWorld& operator=(const RigidWorld&) = delete;

  /// @brief Steps the nearest whole number of substeps to seconds / substep, logging contacts.
  /// @throws std::invalid_argument if seconds < 0 or not finite
  void advance(double seconds);

  /// The log since construction or the last takeContacts(), in time order.
  const std::vector<ContactRecord>& contacts() const;
  /// @return the log, leaving it empty (for long runs written out piecewise)
  std::vector<ContactRecord> takeContacts();

  double time() const;                ///< substeps taken × substep [s]
  std::int64_t substepCount() const;  ///< substeps taken
  double substep() const;             ///< [s]
  int bodyCount() const;              ///< number of specs
  const RigidBodySpec& spec(int body) const;

  double mass(int body) const;        ///< [kg]; 0 for a static body
  Vec3 centreOfMass(int body) const;  ///< world [m]
  BodyPose pose(int body) const;      ///< of the spec's reference point and frame
  BodyVelocity velocity(int body) const;

  /// @brief A force through the centre of mass [N] and a torque [N·m] (world), applied in
  ///        every following substep until changed (buoyancy and drag of the liquid, later).
  /// @throws std::invalid_argument for a static body, an index out of range or a non-finite
  ///         value
  void setExternalForce(int body, const Vec3& force, const Vec3& torque);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace fluidsound::sim
