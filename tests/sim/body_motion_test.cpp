// Tests of sim/body_motion.h: a scene body as a rigid-body spec placed as a solid is, the still
// liquid's buoyancy and drag on a body, and the body as the liquid solver's kinematic solid.
#include "sim/body_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/fluid/solid_rotation.h"

namespace fluidsound::sim {
namespace {

constexpr double kWater = 998.0;  // LiquidForces' default density [kg/m³]

SolidMaterial granite() { return {2650.0, 5.0e10, 0.25, 20.0, 1e-6}; }

/// A tall closed tank of still water, 0.3 × 1.2 × 0.3 m, water up to `level`, one body.
Scene tankWith(const SceneBody& body, double level, double duration) {
  Scene scene;
  scene.domain = {{0, 0, 0}, {0.3, 1.2, 0.3}, 0.05, {}};
  scene.time.duration = duration;
  scene.liquid.push_back({Box{{0, 0, 0}, {0.3, level, 0.3}}, {}});
  scene.bodies.push_back(body);
  return scene;
}

/// The body's vertical speed over the last `keys` path keys [m/s].
double verticalSpeed(const BodyMotion& motion, int body, int keys) {
  const auto& path = motion.paths[body];
  const PathKey& a = path[path.size() - 1 - keys];
  const PathKey& b = path.back();
  return (b.translate[1] - a.translate[1]) / (b.time - a.time);
}

// Claim: a body's frame is the placed shape's centre with the solid's rotation (docs/scene.md,
// "Placement of a solid"), so that the spec puts every point where the solid's placement does.
// Reference: rotateByEulerDegrees (the solids' own placement), to rounding.
TEST(RigidBodySpec, PlacesABoxWhereASolidBoxWouldBe) {
  SceneBody body;
  body.shape = Box{{0.1, 0.2, 0.3}, {0.3, 0.25, 0.4}};
  body.scale = 2.0;
  body.rotateDegrees = {10.0, -25.0, 40.0};
  body.translate = {0.01, 0.02, 0.03};
  body.material = granite();
  const RigidBodySpec spec = rigidBodySpec(body);
  const auto& box = std::get<BoxShape>(spec.shape);
  EXPECT_NEAR(box.halfExtents[0], 0.2, 1e-12);
  EXPECT_NEAR(box.halfExtents[1], 0.05, 1e-12);
  EXPECT_NEAR(box.halfExtents[2], 0.1, 1e-12);
  // The corner (max) of the scaled box, placed as a solid: c₁ + R(p₁ − c₁) + translate.
  const Vec3 c1{0.4, 0.45, 0.7}, corner{0.6, 0.5, 0.8};
  const Vec3 offset = rotateByEulerDegrees({corner[0] - c1[0], corner[1] - c1[1], corner[2] - c1[2]}, body.rotateDegrees);
  const Vec3 bySpec = rotate(spec.rotation, box.halfExtents);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(spec.position[a], c1[a] + body.translate[a], 1e-12);
    EXPECT_NEAR(bySpec[a], offset[a], 1e-12) << a;
  }
  EXPECT_DOUBLE_EQ(spec.density, 2650.0);
  EXPECT_DOUBLE_EQ(contactRadius(spec), 0.05);
}

// Claim: a sphere denser than water sinks at its terminal speed, where the buoyancy and drag of
// the still liquid balance its weight: v_t = √(2(ρ_s − ρ_w)·g·V / (ρ_w·C_d·A)) (Archimedes and
// the quadratic drag law, C_d = 0.47: White, Fluid Mechanics, Fig. 7.16). For a granite sphere of
// 1 cm radius: 0.960 m/s. Tolerance 0.5 %: the sphere's volume and cross-section are exact, the
// speed is measured from Bullet's path over the last 0.1 s (reached after ~4 time constants).
TEST(BodyMotion, SinkingSphereReachesItsTerminalSpeed) {
  SceneBody stone;
  stone.name = "stone";
  stone.shape = Sphere{{0.15, 1.1, 0.15}, 0.01};
  stone.material = granite();
  const Scene scene = tankWith(stone, 1.15, 0.7);
  StageObserver quiet;
  const BodyMotion motion = simulateBodies(scene, quiet);
  const double r = 0.01, volume = 4.0 / 3.0 * std::numbers::pi * r * r * r, area = std::numbers::pi * r * r;
  const double terminal = std::sqrt(2.0 * (2650.0 - kWater) * 9.81 * volume / (kWater * 0.47 * area));
  EXPECT_NEAR(terminal, 0.960, 0.001);
  EXPECT_NEAR(-verticalSpeed(motion, 0, 20), terminal, 0.005 * terminal);
  EXPECT_DOUBLE_EQ(motion.largestSubmergedShare[0], 1.0);
  EXPECT_TRUE(motion.contacts.records.empty()) << "it has not reached the floor";
}

// Claim: a wooden box floats with the share of its height under water equal to its density over
// the water's (Archimedes: 750/998 = 0.7515 of 0.1 m, 75.2 mm). It bobs about that draft at
// ω = √(g/draft) (11.4 rad/s, period 0.55 s; the quadratic drag damps it slowly, and no wave
// radiation is modelled), so the draft is averaged over the last 1.65 s, three periods.
// Tolerance 1.5 mm: the submerged volume is counted on a lattice of 48 points along each axis
// (±1/96 of the height, 1.04 mm) and the average of a decaying bob is not its centre (0.5 mm).
TEST(BodyMotion, FloatingBoxBobsAboutItsDraft) {
  SceneBody box;
  box.shape = Box{{0.1, 0.55, 0.1}, {0.2, 0.65, 0.2}};
  box.material = {750.0, 1.1e10, 0.25, 60.0, 2e-6};
  const Scene scene = tankWith(box, 0.6, 4.0);
  StageObserver quiet;
  LiquidForces liquid;
  liquid.samplesPerAxis = 48;
  const BodyMotion motion = simulateBodies(scene, quiet, liquid);
  double sum = 0.0;
  int count = 0;
  for (const PathKey& key : motion.paths[0])
    if (key.time > 4.0 - 1.65) sum += 0.6 - (0.55 + key.translate[1]), ++count;
  EXPECT_NEAR(sum / count, 0.1 * 750.0 / kWater, 1.5e-3);
  EXPECT_TRUE(motion.contacts.records.empty()) << "it never touches the floor";
}

// Claim: Bullet's stepping is deterministic (rigid_world.h): the same scene gives the same log
// and paths, bit for bit. And the liquid solver sees each body as a solid on that path.
TEST(BodyMotion, SameLogOnEveryRunAndTheBodyIsTheLiquidsSolid) {
  SceneBody stone;
  stone.shape = Sphere{{0.15, 0.3, 0.15}, 0.02};
  stone.material = granite();
  const Scene scene = tankWith(stone, 0.1, 0.5);
  StageObserver quiet;
  const BodyMotion a = simulateBodies(scene, quiet), b = simulateBodies(scene, quiet);
  EXPECT_EQ(a.contacts, b.contacts);
  ASSERT_FALSE(a.contacts.records.empty()) << "it reaches the floor";
  EXPECT_EQ(a.contacts.records.front().bodyB, -3) << "the wall below (−y)";
  const Scene fluid = sceneWithBodiesAsSolids(scene, a);
  ASSERT_EQ(fluid.solids.size(), 1u);
  EXPECT_EQ(fluid.solids[0].path, a.paths[0]);
  EXPECT_NEAR(fluid.solids[0].path.back().translate[1], -(0.3 - 0.02), 1e-3) << "on the floor";
}

}  // namespace
}  // namespace fluidsound::sim
