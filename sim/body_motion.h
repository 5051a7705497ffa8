// sim/body_motion.h — the scene's rigid bodies moved by Bullet (sim/bodies/rigid_world.h) over the
// scene's duration, with the buoyancy and drag of the scene's still liquid, giving the contact log
// that the solids' sound is made from and the path on which the liquid solver sees each body
// (docs/solids.md, "Bodies in run" and "Bodies in the liquid").
//
// Coupling, one way each (issue 22): the liquid pushes a body with the buoyancy and drag of the
// scene's initial liquid regions (boxes and spheres: the still water of a tank or glass, not the
// splash the body makes), and the body pushes the liquid as a kinematic solid that follows the
// translation Bullet gives it (its rotation is not seen by the liquid solver, whose solids only
// translate along a path).
#pragma once

#include <vector>

#include "sim/bodies/rigid_body.h"
#include "sim/core/contact_record.h"
#include "sim/core/stage_observer.h"
#include "sim/scene.h"

namespace fluidsound::sim {

/// @return the world-from-body rotation of a solid's `rotate` (Euler degrees about the fixed x,
///         then y, then z axes: R = Rz·Ry·Rx, sim/fluid/solid_rotation.h) as a unit quaternion
Quaternion quaternionFromEulerDegrees(const Vec3& degrees);

/// @brief A scene body as the rigid-body stage sees it. Its frame: origin at the placed shape's
///        centre c₁ (docs/scene.md, "Placement of a solid": the scaled box's or sphere's centre, or
///        the scaled mesh's bounding-box centre), axes the shape's own; position c₁ + translate,
///        rotation `rotate`. A mesh is its scaled triangles less c₁. The modal model of the body
///        is made in this frame (tools/body_modes.h), so contact points in it need no conversion.
RigidBodySpec rigidBodySpec(const SceneBody& body);

/// @brief The radius of curvature a Hertz contact with the body sees [m]: a sphere's radius, else
///        half the smallest side of its bounding box in its frame (a choice for corners and faces
///        of boxes and meshes: docs/solids.md, Impacts).
double contactRadius(const RigidBodySpec& spec);

/// How the still liquid acts on a body (one way).
struct LiquidForces {
  double density = 998.0;  ///< ρ_w [kg/m³] (physics.md §2, 20 °C)
  /// C_d of the quadratic drag ½ρ_w·C_d·A·|v|·v on the submerged share of the body, A the
  /// cross-section of the sphere of the body's volume: a sphere's 0.47 at Re 10³–10⁵ (White,
  /// Fluid Mechanics, Fig. 7.16), used for every shape (a choice: documented).
  double dragCoefficient = 0.47;
  int samplesPerAxis = 12;  ///< the body's volume as up to n³ points, for its submerged share
};

/// What the rigid-body stage made.
struct BodyMotion {
  ContactLog contacts;
  /// Per body: its reference point's displacement from t = 0, keyed every pathInterval and at
  /// the end (the liquid solver's `path` of the body).
  std::vector<std::vector<PathKey>> paths;
  double pathInterval = 5e-3;  ///< [s]
  /// Per body: the largest share of its volume that was in the liquid, 0 … 1.
  std::vector<double> largestSubmergedShare;
};

/// @brief Bullet over the scene's duration at 1 ms substeps (the domain's closed faces as walls,
///        the scene's gravity), each dynamic body pushed by the still liquid every substep
///        (Archimedes' buoyancy ρ_w·V_sub·(−g) at the submerged centroid, and drag), logging
///        every contact. Deterministic (RigidWorld's note).
/// @param observer  progress in simulated seconds; wasInterrupted() every 10 ms stops with
///        StageInterrupted("bodies at t = … s")
/// @throws std::invalid_argument for a body Bullet cannot take (RigidWorld's checks)
BodyMotion simulateBodies(const Scene& scene, StageObserver& observer, const LiquidForces& liquid = {});

/// @brief The scene with each body added to its solids as a kinematic solid on its path (the
///        body's shape, scale, rotation and translation at t = 0; a mesh's triangles placed).
Scene sceneWithBodiesAsSolids(const Scene& scene, const BodyMotion& motion);

}  // namespace fluidsound::sim
