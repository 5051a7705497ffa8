// sim/body_motion.h — the scene's rigid bodies moved by Bullet (sim/bodies/rigid_world.h) over the
// scene's duration, with the buoyancy and drag of the scene's still liquid, giving the contact log
// that the solids' sound is made from and the path on which the liquid solver sees each body
// (docs/solids.md, "Bodies in run" and "Bodies in the liquid").
//
// Coupling, one way each, frame by frame (issue 22; sim::simulate does it): before each frame the
// bodies are stepped to its end, pushed by the buoyancy and drag of the liquid the frame before
// left around them; then the liquid solver sees each as a kinematic solid on the path Bullet gave
// it (translation only: the solver's solids do not turn).
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "sim/bodies/rigid_body.h"
#include "sim/core/contact_record.h"
#include "sim/core/stage_observer.h"
#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
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

/// Where the liquid is: true for a world point [m] inside it.
using LiquidRegionTest = std::function<bool(const Vec3&)>;

/// @brief The scene's bodies in Bullet (1 ms substeps, the domain's closed faces as walls, the
///        scene's gravity), stepped on demand: each dynamic body pushed every substep by the
///        liquid that `advanceTo` is told of — Archimedes' buoyancy ρ_w·V_sub·(−g) at the
///        submerged centroid, and drag — with every contact logged. Deterministic (RigidWorld's
///        note).
class BodyStepper {
 public:
  /// @throws std::invalid_argument for a body Bullet cannot take (RigidWorld's checks)
  explicit BodyStepper(const Scene& scene, const LiquidForces& liquid = {});
  ~BodyStepper();
  BodyStepper(BodyStepper&&) noexcept;
  BodyStepper& operator=(BodyStepper&&) = delete;
  /// @brief Steps the whole substeps up to `time` [s] with the liquid where `inLiquid` says (an
  ///        empty test: no liquid, and no time spent looking for it).
  /// @return each body's path keys added by this call (one list per body)
  std::vector<std::vector<PathKey>> advanceTo(double time, const LiquidRegionTest& inLiquid);
  double time() const;
  /// The motion so far (the contact log's duration: the time stepped to).
  BodyMotion motion() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// @brief The liquid around the bodies as the liquid solver left it: a point is in the liquid
///        when φ < 0 there, or when at least two of the four points `reach` [m] away from it
///        across the horizontal (perpendicular to the gravity's main axis) are — a body is a solid
///        to the solver, so φ inside it is air's, and the level around it stands for the level
///        through it (as the solver's own pressure φ continues a flat surface through a solid).
/// @param phi  the solver's liquid φ at cell centres [m] (FluidSolver::liquidDistance); it must
///        outlive the returned test
LiquidRegionTest liquidAround(const Array3f& phi, const GridGeometry& grid, const Vec3& gravity, double reach);

/// @return the largest distance of a point of any body from its reference point [m]
double largestBodyRadius(const Scene& scene);

/// @return whether `p` [m] lies in one of the scene's initial liquid boxes or spheres (its still
///         water: a tank's, a glass's)
bool inInitialLiquid(const Scene& scene, const Vec3& p);

/// @brief The bodies alone over the scene's duration, pushed by its still initial liquid
///        (inInitialLiquid): the stage without the liquid solver (tests, and scenes the liquid
///        does not reach).
/// @param observer  progress in simulated seconds; wasInterrupted() every 10 ms stops with
///        StageInterrupted("bodies at t = … s")
BodyMotion simulateBodies(const Scene& scene, StageObserver& observer, const LiquidForces& liquid = {});

/// @brief The scene with each body added to its solids as a kinematic solid on its path (the
///        body's shape, scale, rotation and translation at t = 0; a mesh's triangles placed).
Scene sceneWithBodiesAsSolids(const Scene& scene, const BodyMotion& motion);

}  // namespace fluidsound::sim
