// sim/bodies/rigid_world.cpp — Bullet world of the sounding solids, stepped per substep, with
// the contact log.
#include "sim/bodies/rigid_world.h"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/bodies/bullet_shape.h"
#include "sim/bodies/contact_kinematics.h"

namespace fluidsound::sim {
namespace {

/// A rotation whose norm is off by more than this is a mistake, not rounding.
constexpr double kUnitQuaternionTolerance = 1e-6;

/// The dynamics world with one change: the rolling-resistance arm of a contact is the sum of
/// the two bodies' arms (RigidBodySpec), set on every manifold point between the collision
/// detection and the solve, in place of Bullet's product.
class SoundingDynamicsWorld final : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;

  void solveConstraints(btContactSolverInfo& solverInfo) override {
    btDispatcher* dispatcher = getDispatcher();
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      const btScalar arm =
          manifold->getBody0()->getRollingFriction() + manifold->getBody1()->getRollingFriction();
      for (int p = 0; p < manifold->getNumContacts(); ++p)
        manifold->getContactPoint(p).m_combinedRollingFriction = arm;
    }
    btDiscreteDynamicsWorld::solveConstraints(solverInfo);
  }
};

Vec3 toVec3(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
btVector3 toBt(const Vec3& v) { return btVector3(v[0], v[1], v[2]); }

bool finite(const Vec3& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

[[noreturn]] void rejectSetting(const std::string& field, const std::string& expected,
                                double found) {
  throw std::invalid_argument("RigidWorldSettings." + field + ": expected " + expected +
                              ", found " + std::to_string(found));
}

void validate(const RigidWorldSettings& s) {
  if (!(s.substep > 0.0 && s.substep <= kMaxRigidSubstep))
    rejectSetting("substep", "0 < substep ≤ 0.001 s", s.substep);
  if (!finite(s.gravity)) throw std::invalid_argument("RigidWorldSettings.gravity: not finite");
  if (!(s.contactDistance >= 0.0 && std::isfinite(s.contactDistance)))
    rejectSetting("contactDistance", "a finite distance ≥ 0 m", s.contactDistance);
  if (!(s.restitutionSpeedThreshold >= 0.0 && std::isfinite(s.restitutionSpeedThreshold)))
    rejectSetting("restitutionSpeedThreshold", "a finite speed ≥ 0 m/s",
                  s.restitutionSpeedThreshold);
  if (s.solverIterations < 1) rejectSetting("solverIterations", "≥ 1", s.solverIterations);
}

void validate(const RigidBodySpec& spec) {
  const auto reject = [&](const std::string& what) {
    throw std::invalid_argument("rigid body '" + spec.name + "': " + what);
  };
  if (!(spec.friction >= 0.0 && std::isfinite(spec.friction)))
    reject("friction must be a finite μ ≥ 0, got " + std::to_string(spec.friction));
  if (!(spec.restitution >= 0.0 && spec.restitution <= 1.0))
    reject("restitution must be in [0, 1], got " + std::to_string(spec.restitution));
  if (!(spec.rollingFriction >= 0.0 && std::isfinite(spec.rollingFriction)))
    reject("rollingFriction must be a finite arm ≥ 0 m, got " +
           std::to_string(spec.rollingFriction));
  if (!finite(spec.position) || !finite(spec.velocity) || !finite(spec.angularVelocity))
    reject("position, velocity and angular velocity must be finite");
  const Quaternion& q = spec.rotation;
  const double norm = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  if (!(std::abs(norm - 1.0) <= kUnitQuaternionTolerance))
    reject("rotation must be a unit quaternion, its norm is " + std::to_string(norm));
}

}  // namespace

struct RigidWorld::State {
  RigidWorldSettings settings;
  std::vector<RigidBodySpec> specs;
  std::vector<BulletShape> shapes;             ///< one per spec
  std::vector<btTransform> bodyFromReference;  ///< one per spec
  std::vector<std::unique_ptr<btBoxShape>> wallShapes;
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  SoundingDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  /// Specs first (collision-object user index = spec index), then walls (n + face).
  std::vector<std::unique_ptr<btRigidBody>> objects;
  std::vector<Vec3> externalForce, externalTorque;  ///< one per spec [N], [N·m]
  std::vector<BodyMotion> motionBefore;             ///< one per spec, scratch of step()
  std::vector<Quaternion> orientationBefore;        ///< world-from-reference, scratch of step()
  std::vector<ContactRecord> log;
  std::int64_t substeps = 0;

  ~State() {
    for (auto it = objects.rbegin(); it != objects.rend(); ++it) world.removeRigidBody(it->get());
  }

  int bodyCount() const { return int(specs.size()); }

  /// The log's index of a collision object: its spec index, or −1 − face for a wall.
  int logIndex(const btCollisionObject* object) const {
    const int key = object->getUserIndex();
    return key < bodyCount() ? key : -1 - (key - bodyCount());
  }

  void addObject(std::unique_ptr<btRigidBody> body, int key) {
    body->setUserIndex(key);
    body->setContactProcessingThreshold(settings.contactDistance);
    world.addRigidBody(body.get());
    objects.push_back(std::move(body));
  }

  void addBody(int index) {
    const RigidBodySpec& spec = specs[index];
    BulletShape& shape = shapes[index];
    const Quaternion& q = spec.rotation;
    const btTransform worldFromReference(btQuaternion(q.x, q.y, q.z, q.w).normalized(),
                                         toBt(spec.position));
    btRigidBody::btRigidBodyConstructionInfo info(shape.mass, nullptr, shape.shape.get(),
                                                  shape.principalMoments);
    info.m_startWorldTransform = worldFromReference * shape.referenceFromBody;
    info.m_friction = spec.friction;
    info.m_restitution = spec.restitution;
    info.m_rollingFriction = spec.rollingFriction;
    auto body = std::make_unique<btRigidBody>(info);
    if (!spec.isStatic) {
      body->setActivationState(DISABLE_DEACTIVATION);
      body->setLinearVelocity(toBt(spec.velocity));
      body->setAngularVelocity(toBt(spec.angularVelocity));
    }
    addObject(std::move(body), index);
  }

  void addWalls(const DomainBox& domain) {
    double thickness = 0.0;  // as thick as the domain is wide: nothing crosses that in a substep
    for (int a = 0; a < 3; ++a) thickness = std::max(thickness, domain.max[a] - domain.min[a]);
    for (const WallBox& wall : domainWalls(domain, thickness)) {
      const Vec3& h = wall.halfExtents;
      auto shape = std::make_unique<btBoxShape>(toBt(h));
      shape->setMargin(std::min(kMaxCollisionMargin, 0.1 * std::min({h[0], h[1], h[2]})));
      btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, shape.get());
      info.m_startWorldTransform = btTransform(btQuaternion::getIdentity(), toBt(wall.centre));
      info.m_friction = domain.friction;
      info.m_restitution = domain.restitution;
      info.m_rollingFriction = domain.rollingFriction;
      wallShapes.push_back(std::move(shape));
      addObject(std::make_unique<btRigidBody>(info), bodyCount() + static_cast<int>(wall.face));
    }
  }

  void step() {
    const double dt = settings.substep;
    for (int i = 0; i < bodyCount(); ++i) {
      const btRigidBody& body = *objects[i];
      motionBefore[i] = {toVec3(body.getCenterOfMassPosition()), toVec3(body.getLinearVelocity()),
                         toVec3(body.getAngularVelocity())};
      const btQuaternion q = (body.getWorldTransform() * bodyFromReference[i]).getRotation();
      orientationBefore[i] = {q.w(), q.x(), q.y(), q.z()};
    }
    for (int i = 0; i < bodyCount(); ++i) {
      if (specs[i].isStatic) continue;
      objects[i]->applyCentralForce(toBt(externalForce[i]));
      objects[i]->applyTorque(toBt(externalTorque[i]));
    }
    // One internal step: the accumulator starts at 0 and gains exactly one fixed step.
    world.stepSimulation(dt, 1, dt);
    ++substeps;
    appendContacts(double(substeps) * dt);
  }

  void appendContacts(double time) {
    const std::size_t first = log.size();
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      const btCollisionObject* object0 = manifold->getBody0();
      const btCollisionObject* object1 = manifold->getBody1();
      // Bullet's normal points from body1 into body0; A is the object with the smaller key.
      const bool swapped = object0->getUserIndex() > object1->getUserIndex();
      const btCollisionObject* objectA = swapped ? object1 : object0;
      const btCollisionObject* objectB = swapped ? object0 : object1;
      const int keyA = objectA->getUserIndex();
      const int keyB = objectB->getUserIndex();
      const double sign = swapped ? -1.0 : 1.0;
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        const btManifoldPoint& point = manifold->getContactPoint(p);
        if (point.getDistance() > manifold->getContactProcessingThreshold()) continue;
        ContactRecord record;
        record.time = time;
        record.bodyA = logIndex(objectA);
        record.bodyB = logIndex(objectB);
        const btVector3 position =
            0.5 * (point.getPositionWorldOnA() + point.getPositionWorldOnB());
        record.position = toVec3(position);
        record.normal = toVec3(sign * point.m_normalWorldOnB);
        record.normalImpulse = point.getAppliedImpulse();
        record.frictionImpulse =
            toVec3(sign * (point.m_appliedImpulseLateral1 * point.m_lateralFrictionDir1 +
                           point.m_appliedImpulseLateral2 * point.m_lateralFrictionDir2));
        const ContactKinematics k =
            contactKinematics(motionOf(keyA), motionOf(keyB), record.position, record.normal);
        record.normalSpeed = k.normalSpeed;
        record.tangentialSpeed = k.tangentialSpeed;
        record.rollingRate = k.rollingRate;
        record.lifetime = point.getLifeTime();
        const btVector3 local0 =
            pointInSpecFrame(object0, point.m_localPointA, point.getPositionWorldOnA());
        const btVector3 local1 =
            pointInSpecFrame(object1, point.m_localPointB, point.getPositionWorldOnB());
        record.localPointA = toVec3(swapped ? local1 : local0);
        record.localPointB = toVec3(swapped ? local0 : local1);
        record.orientationA = orientationOf(keyA);
        record.orientationB = orientationOf(keyB);
        log.push_back(record);
      }
    }
    std::stable_sort(log.begin() + std::ptrdiff_t(first), log.end(),
                     [](const ContactRecord& a, const ContactRecord& b) {
                       return std::pair(a.bodyA, a.bodyB) < std::pair(b.bodyA, b.bodyB);
                     });
  }

  /// A body's motion at the start of the substep; a wall does not move.
  BodyMotion motionOf(int key) const {
    return key < bodyCount() ? motionBefore[key] : BodyMotion{};
  }

  /// A body's world-from-reference rotation at the start of the substep; a wall's is the identity.
  Quaternion orientationOf(int key) const {
    return key < bodyCount() ? orientationBefore[key] : Quaternion{};
  }

  /// A contact point of `object` in its spec's frame, from Bullet's body frame; a wall's in
  /// world space.
  btVector3 pointInSpecFrame(const btCollisionObject* object, const btVector3& inBody,
                             const btVector3& inWorld) const {
    const int key = object->getUserIndex();
    return key < bodyCount() ? shapes[key].referenceFromBody * inBody : inWorld;
  }

  void checkBody(int body, const char* what) const {
    if (body < 0 || body >= bodyCount())
      throw std::invalid_argument(std::string("RigidWorld::") + what + ": no body " +
                                  std::to_string(body) + " (there are " +
                                  std::to_string(bodyCount()) + ")");
  }
};

RigidWorld::RigidWorld(std::vector<RigidBodySpec> bodies, const RigidWorldSettings& settings)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  validate(settings);
  s.settings = settings;
  s.specs = std::move(bodies);
  for (const RigidBodySpec& spec : s.specs) {
    validate(spec);
    s.shapes.push_back(makeBulletShape(spec));
    s.bodyFromReference.push_back(s.shapes.back().referenceFromBody.inverse());
  }
  s.world.setGravity(toBt(settings.gravity));  // before adding bodies: they copy it
  btContactSolverInfo& solverInfo = s.world.getSolverInfo();
  solverInfo.m_numIterations = settings.solverIterations;
  solverInfo.m_solverMode =
      SOLVER_USE_WARMSTARTING | SOLVER_SIMD | SOLVER_USE_2_FRICTION_DIRECTIONS;
  solverInfo.m_restitutionVelocityThreshold = settings.restitutionSpeedThreshold;
  // Split impulse for every penetration, not only beyond Bullet's default 4 cm: the position
  // correction (erp2 = 0.2 of the depth per substep) then moves bodies by pseudo-velocities
  // and stays out of the applied impulse. Otherwise an impact found 1 mm deep at 2 m/s would
  // log 0.2·depth/substep ≈ 0.2 m/s of extra approach, ~8 % too much impulse.
  solverInfo.m_splitImpulse = true;
  solverInfo.m_splitImpulsePenetrationThreshold = 0.0;
  for (int i = 0; i < s.bodyCount(); ++i) s.addBody(i);
  if (settings.domain) s.addWalls(*settings.domain);
  s.externalForce.assign(s.specs.size(), Vec3{});
  s.externalTorque.assign(s.specs.size(), Vec3{});
  s.motionBefore.assign(s.specs.size(), BodyMotion{});
  s.orientationBefore.assign(s.specs.size(), Quaternion{});
}

RigidWorld::~RigidWorld() = default;
RigidWorld::RigidWorld(RigidWorld&&) noexcept = default;
RigidWorld& RigidWorld::operator=(RigidWorld&&) noexcept = default;

void RigidWorld::advance(double seconds) {
  if (!(seconds >= 0.0 && std::isfinite(seconds)))
    throw std::invalid_argument("RigidWorld::advance: seconds must be finite and ≥ 0, got " +
                                std::to_string(seconds));
  const long long count = std::llround(seconds / state_->settings.substep);
  for (long long k = 0; k < count; ++k) state_->step();
}

const std::vector<ContactRecord>& RigidWorld::contacts() const { return state_->log; }

std::vector<ContactRecord> RigidWorld::takeContacts() { return std::exchange(state_->log, {}); }

double RigidWorld::time() const { return double(state_->substeps) * state_->settings.substep; }
std::int64_t RigidWorld::substepCount() const { return state_->substeps; }
double RigidWorld::substep() const { return state_->settings.substep; }
int RigidWorld::bodyCount() const { return state_->bodyCount(); }

const RigidBodySpec& RigidWorld::spec(int body) const {
  state_->checkBody(body, "spec");
  return state_->specs[body];
}

double RigidWorld::mass(int body) const {
  state_->checkBody(body, "mass");
  return state_->shapes[body].mass;
}

Vec3 RigidWorld::centreOfMass(int body) const {
  state_->checkBody(body, "centreOfMass");
  return toVec3(state_->objects[body]->getCenterOfMassPosition());
}

BodyPose RigidWorld::pose(int body) const {
  state_->checkBody(body, "pose");
  const btTransform worldFromReference =
      state_->objects[body]->getWorldTransform() * state_->bodyFromReference[body];
  const btQuaternion q = worldFromReference.getRotation();
  return {toVec3(worldFromReference.getOrigin()), Quaternion{q.w(), q.x(), q.y(), q.z()}};
}

BodyVelocity RigidWorld::velocity(int body) const {
  state_->checkBody(body, "velocity");
  const btRigidBody& b = *state_->objects[body];
  return {toVec3(b.getLinearVelocity()), toVec3(b.getAngularVelocity())};
}

void RigidWorld::setExternalForce(int body, const Vec3& force, const Vec3& torque) {
  state_->checkBody(body, "setExternalForce");
  if (state_->specs[body].isStatic)
    throw std::invalid_argument("RigidWorld::setExternalForce: body '" + state_->specs[body].name +
                                "' is static");
  if (!finite(force) || !finite(torque))
    throw std::invalid_argument("RigidWorld::setExternalForce: force and torque must be finite");
  state_->externalForce[body] = force;
  state_->externalTorque[body] = torque;
}

}  // namespace fluidsound::sim
