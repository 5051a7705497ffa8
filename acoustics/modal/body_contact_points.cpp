// acoustics/modal/body_contact_points.cpp — see body_contact_points.h.
#include "acoustics/modal/body_contact_points.h"

#include <stdexcept>

namespace fluidsound::acoustics {

namespace {

Eigen::Vector3d eigen(const Vec3& v) { return {v[0], v[1], v[2]}; }
Eigen::Quaterniond eigen(const sim::Quaternion& q) { return Eigen::Quaterniond(q.w, q.x, q.y, q.z); }

}  // namespace

std::vector<BodyContactPoint> bodyContactPoints(const sim::ContactLog& log, int body) {
  if (body < 0 || body >= static_cast<int>(log.bodies.size()))
    throw std::invalid_argument("bodyContactPoints: no body " + std::to_string(body) + " in the log");
  const auto moves = [&log](int index) {
    return index >= 0 && !log.bodies[static_cast<std::size_t>(index)].isStatic;
  };
  std::vector<BodyContactPoint> points;
  for (const sim::ContactRecord& c : log.records) {
    if (c.bodyA != body && c.bodyB != body) continue;
    const bool isA = c.bodyA == body;
    const int other = isA ? c.bodyB : c.bodyA;
    const double sign = isA ? 1.0 : -1.0;  // the record's impulse and normal are A's
    const Eigen::Quaterniond orientation = eigen(isA ? c.orientationA : c.orientationB);
    const Eigen::Quaterniond bodyFromWorld = orientation.conjugate();
    const Eigen::Vector3d ownPoint = eigen(isA ? c.localPointA : c.localPointB);
    const Eigen::Vector3d otherPoint = eigen(isA ? c.localPointB : c.localPointA);
    BodyContactPoint p;
    p.time = c.time;
    p.other = other;
    p.localPoint = ownPoint;
    p.normal = bodyFromWorld * (sign * eigen(c.normal));
    p.impulse = bodyFromWorld * (sign * (c.normalImpulse * eigen(c.normal) + eigen(c.frictionImpulse)));
    p.normalSpeed = c.normalSpeed;
    p.normalImpulse = c.normalImpulse;
    p.tangentialSpeed = c.tangentialSpeed;
    p.rollingSpeed = c.rollingRate * (moves(other) ? otherPoint.norm() : ownPoint.norm());
    p.orientation = orientation;
    p.origin = eigen(c.position) - orientation * ownPoint;
    points.push_back(p);
  }
  return points;
}

}  // namespace fluidsound::acoustics
