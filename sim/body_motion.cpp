// sim/body_motion.cpp — see body_motion.h.
#include "sim/body_motion.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <variant>

#include "sim/bodies/body_segment.h"
#include "sim/bodies/rigid_world.h"
#include "sim/core/vec3_math.h"
#include "sim/fluid/cell_interpolation.h"
#include "sim/fluid/solid_rotation.h"

namespace fluidsound::sim {

namespace {


/// The placed shape's centre c₁ (scaled) and, for a mesh, its scaled vertices' bounds.
Vec3 shapeCentre(const SceneBody& body) {
  if (const auto* box = std::get_if<Box>(&body.shape))
    return scaled(add(box->min, box->max), 0.5 * body.scale);
  if (const auto* sphere = std::get_if<Sphere>(&body.shape)) return scaled(sphere->center, body.scale);
  const TriangleMesh& mesh = *std::get<MeshFile>(body.shape).surface;  // scaled already (io)
  Vec3 lo{}, hi{};
  lo.fill(std::numeric_limits<double>::max());
  hi.fill(-std::numeric_limits<double>::max());
  for (const auto& v : mesh.vertices)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], double(v[a])), hi[a] = std::max(hi[a], double(v[a]));
  return scaled(add(lo, hi), 0.5);
}

/// Points filling a body's shape (its frame), each standing for the same volume: the centres of
/// an n³ lattice over its bounding box that lie inside it (nudged off symmetry planes, so that no
/// point lies on a mesh's edge for the ray test).
std::vector<Vec3> volumePoints(const RigidBodySpec& spec, int perAxis) {
  const Vec3 half = boundingHalfExtents(spec);
  const auto at = [perAxis](double h, int i, double nudge) { return h * ((2.0 * i + 1.0) / perAxis - 1.0 + nudge); };
  std::vector<Vec3> points;
  for (int i = 0; i < perAxis; ++i)
    for (int j = 0; j < perAxis; ++j)
      for (int k = 0; k < perAxis; ++k) {
        const Vec3 p{at(half[0], i, 1e-9), at(half[1], j, 1.3e-9), at(half[2], k, 0.7e-9)};
        if (bodyContainsPoint(spec, p)) points.push_back(p);
      }
  return points;
}

/// The still liquid's force and torque (about the centre of mass) on one dynamic body.
struct LiquidPush {
  Vec3 force{}, torque{};
  double submergedShare = 0.0;
};

LiquidPush liquidPush(const Vec3& gravity, const RigidWorld& world, int body, const std::vector<Vec3>& points,
                      double volume, const LiquidForces& liquid, const LiquidRegionTest& inLiquid) {
  const BodyPose pose = world.pose(body);
  Vec3 centroid{};
  std::size_t wet = 0;
  for (const Vec3& p : points) {
    const Vec3 x = add(pose.position, rotate(pose.orientation, p));
    if (inLiquid(x)) {
      centroid = add(centroid, x);
      ++wet;
    }
  }
  LiquidPush push;
  if (wet == 0 || points.empty()) return push;
  push.submergedShare = double(wet) / double(points.size());
  centroid = scaled(centroid, 1.0 / double(wet));
  const double submerged = volume * push.submergedShare;
  // Archimedes: the displaced liquid's weight, up against gravity, at the submerged centroid.
  const Vec3 buoyancy = scaled(gravity, -liquid.density * submerged);
  // Quadratic drag on the sphere of the body's volume, by the submerged share.
  const Vec3 v = world.velocity(body).linear;
  const double radius = std::cbrt(3.0 * volume / (4.0 * std::numbers::pi));
  const double area = std::numbers::pi * radius * radius;
  const Vec3 drag = scaled(v, -0.5 * liquid.density * liquid.dragCoefficient * area * push.submergedShare *
                                  std::sqrt(dot(v, v)));
  push.force = add(buoyancy, drag);
  push.torque = cross(sub(centroid, world.centreOfMass(body)), buoyancy);
  return push;
}

DomainBox domainBox(const Domain& domain) {
  DomainBox box{domain.min, domain.max, {}};
  for (int f = 0; f < 6; ++f)
    if (domain.open[f]) box.openFaces.push_back(static_cast<DomainFace>(f));
  return box;
}

}  // namespace

Quaternion quaternionFromEulerDegrees(const Vec3& degrees) {
  const double toRadians = std::numbers::pi / 180.0;
  const Quaternion qx = quaternionFromAxisAngle({1, 0, 0}, degrees[0] * toRadians);
  const Quaternion qy = quaternionFromAxisAngle({0, 1, 0}, degrees[1] * toRadians);
  const Quaternion qz = quaternionFromAxisAngle({0, 0, 1}, degrees[2] * toRadians);
  return qz * qy * qx;
}

RigidBodySpec rigidBodySpec(const SceneBody& body) {
  RigidBodySpec spec;
  spec.name = body.name;
  const Vec3 centre = shapeCentre(body);
  if (const auto* box = std::get_if<Box>(&body.shape)) {
    spec.shape = BoxShape{scaled(sub(box->max, box->min), 0.5 * body.scale)};
  } else if (const auto* sphere = std::get_if<Sphere>(&body.shape)) {
    spec.shape = SphereShape{sphere->radius * body.scale};
  } else {
    TriangleMesh mesh = *std::get<MeshFile>(body.shape).surface;
    for (auto& v : mesh.vertices)
      for (int a = 0; a < 3; ++a) v[a] = static_cast<float>(double(v[a]) - centre[a]);
    spec.shape = std::move(mesh);
  }
  spec.density = body.material.density;
  spec.isStatic = body.isStatic;
  spec.position = add(centre, body.translate);
  spec.rotation = quaternionFromEulerDegrees(body.rotateDegrees);
  spec.velocity = body.velocity;
  spec.angularVelocity = body.angularVelocity;
  spec.friction = body.friction;
  spec.restitution = body.restitution;
  return spec;
}

double contactRadius(const RigidBodySpec& spec) {
  if (const auto* sphere = std::get_if<SphereShape>(&spec.shape)) return sphere->radius;
  const Vec3 half = boundingHalfExtents(spec);
  return std::min({half[0], half[1], half[2]});
}

LiquidRegionTest liquidAround(const Array3f& phi, const GridGeometry& grid, const Vec3& gravity, double reach) {
  int up = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(gravity[a]) > std::abs(gravity[up])) up = a;
  const int across1 = (up + 1) % 3, across2 = (up + 2) % 3;
  return [&phi, &grid, across1, across2, reach](const Vec3& p) {
    if (interpolateCellCentres(phi, grid, p) < 0.0) return true;
    int wet = 0;
    for (const int axis : {across1, across2})
      for (const double side : {-reach, reach}) {
        Vec3 q = p;
        q[axis] += side;
        wet += interpolateCellCentres(phi, grid, q) < 0.0 ? 1 : 0;
      }
    return wet >= 2;
  };
}

double largestBodyRadius(const Scene& scene) {
  double largest = 0.0;
  for (const SceneBody& body : scene.bodies) largest = std::max(largest, boundingRadius(rigidBodySpec(body)));
  return largest;
}

bool inInitialLiquid(const Scene& scene, const Vec3& p) {
  for (const LiquidRegion& region : scene.liquid) {
    if (const auto* box = std::get_if<Box>(&region.shape)) {
      if (p[0] >= box->min[0] && p[0] <= box->max[0] && p[1] >= box->min[1] && p[1] <= box->max[1] &&
          p[2] >= box->min[2] && p[2] <= box->max[2])
        return true;
    } else if (const auto* sphere = std::get_if<Sphere>(&region.shape)) {
      const Vec3 d = sub(p, sphere->center);
      if (dot(d, d) <= sphere->radius * sphere->radius) return true;
    }
  }
  return false;
}

struct BodyStepper::State {
  std::vector<RigidBodySpec> specs;
  RigidWorld world;
  LiquidForces liquid;
  Vec3 gravity{};
  BodyMotion motion;
  std::vector<std::vector<Vec3>> points;  ///< each dynamic body's volume, its frame
  std::vector<double> volumes;
  std::vector<Vec3> start;  ///< each body's reference point at t = 0
  std::int64_t keyEvery = 5;

  State(std::vector<RigidBodySpec> s, const RigidWorldSettings& settings) : specs(s), world(std::move(s), settings) {}
};

BodyStepper::BodyStepper(const Scene& scene, const LiquidForces& liquid) {
  std::vector<RigidBodySpec> specs;
  for (const SceneBody& body : scene.bodies) specs.push_back(rigidBodySpec(body));
  RigidWorldSettings settings;
  settings.gravity = scene.gravity;
  settings.domain = domainBox(scene.domain);
  state_ = std::make_unique<State>(std::move(specs), settings);
  State& s = *state_;
  s.liquid = liquid;
  s.gravity = scene.gravity;
  s.motion.contacts.substep = s.world.substep();
  const int n = s.world.bodyCount();
  s.points.resize(n);
  s.volumes.assign(n, 0.0);
  s.motion.paths.assign(n, {});
  s.motion.largestSubmergedShare.assign(n, 0.0);
  s.keyEvery = std::max<std::int64_t>(1, std::llround(s.motion.pathInterval / s.world.substep()));
  for (int b = 0; b < n; ++b) {
    const RigidBodySpec& spec = s.specs[b];
    s.motion.contacts.bodies.push_back({spec.name, s.world.mass(b), spec.isStatic, contactRadius(spec)});
    s.start.push_back(s.world.pose(b).position);
    s.motion.paths[b].push_back({0.0, {0.0, 0.0, 0.0}});
    if (!spec.isStatic) {
      s.points[b] = volumePoints(spec, liquid.samplesPerAxis);
      s.volumes[b] = s.world.mass(b) / spec.density;  // exact (sim/bodies/body_mass.h for meshes)
    }
  }
}

BodyStepper::~BodyStepper() = default;
BodyStepper::BodyStepper(BodyStepper&&) noexcept = default;

double BodyStepper::time() const { return state_->world.time(); }

std::vector<std::vector<PathKey>> BodyStepper::advanceTo(double time, const LiquidRegionTest& inLiquid) {
  State& s = *state_;
  const int n = s.world.bodyCount();
  std::vector<std::vector<PathKey>> added(n);
  const auto target = static_cast<std::int64_t>(std::llround(time / s.world.substep()));
  while (s.world.substepCount() < target) {
    for (int b = 0; b < n && inLiquid; ++b) {
      if (s.specs[b].isStatic) continue;
      const LiquidPush push = liquidPush(s.gravity, s.world, b, s.points[b], s.volumes[b], s.liquid, inLiquid);
      s.world.setExternalForce(b, push.force, push.torque);
      s.motion.largestSubmergedShare[b] = std::max(s.motion.largestSubmergedShare[b], push.submergedShare);
    }
    s.world.advance(s.world.substep());
    const std::int64_t done = s.world.substepCount();
    if (done % s.keyEvery == 0 || done == target)
      for (int b = 0; b < n; ++b) {
        const PathKey key{s.world.time(), sub(s.world.pose(b).position, s.start[b])};
        if (key.time > s.motion.paths[b].back().time) {
          s.motion.paths[b].push_back(key);
          added[b].push_back(key);
        }
      }
  }
  std::vector<ContactRecord> records = s.world.takeContacts();
  s.motion.contacts.records.insert(s.motion.contacts.records.end(), records.begin(), records.end());
  s.motion.contacts.duration = s.world.time();
  return added;
}

BodyMotion BodyStepper::motion() const { return state_->motion; }

BodyMotion simulateBodies(const Scene& scene, StageObserver& observer, const LiquidForces& liquid) {
  BodyStepper stepper(scene, liquid);
  const LiquidRegionTest still = [&scene](const Vec3& p) { return inInitialLiquid(scene, p); };
  observer.started(scene.time.duration);
  constexpr double kChunk = 0.01;  // [s] between progress reports and interruption checks
  const auto chunks = static_cast<long long>(std::ceil(scene.time.duration / kChunk - 1e-9));
  for (long long c = 1; c <= chunks; ++c) {
    if (observer.wasInterrupted()) throw StageInterrupted("bodies at t = " + std::to_string(stepper.time()) + " s");
    stepper.advanceTo(std::min(scene.time.duration, double(c) * kChunk), still);
    observer.progress(double(c) / double(chunks));
  }
  return stepper.motion();
}

Scene sceneWithBodiesAsSolids(const Scene& scene, const BodyMotion& motion) {
  Scene out = scene;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const SceneBody& body = scene.bodies[b];
    Solid solid{body.shape, body.scale, body.rotateDegrees, body.translate, {}};
    if (const auto* mesh = std::get_if<MeshFile>(&body.shape)) {
      // A solid mesh's triangles are placed (io places the scene's own when it reads them).
      const Vec3 centre = shapeCentre(body);
      auto placed = std::make_shared<TriangleMesh>(*mesh->surface);
      for (auto& v : placed->vertices) {
        const Vec3 p = add(add(centre, rotateByEulerDegrees(sub({v[0], v[1], v[2]}, centre), body.rotateDegrees)),
                           body.translate);
        v = {float(p[0]), float(p[1]), float(p[2])};
      }
      solid.shape = MeshFile{mesh->file, placed};
    }
    if (!body.isStatic && b < motion.paths.size()) solid.path = motion.paths[b];
    out.solids.push_back(std::move(solid));
  }
  return out;
}

}  // namespace fluidsound::sim
