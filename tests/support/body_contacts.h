// tests/support/body_contacts.h — the rigid-body stage's contact log (sim::ContactRecord) as one
// body's contact points (acoustics::BodyContactPoint): that body's side of each record, in its
// own frame. (The contact log's file reader will do the same for `run`.)
#pragma once

#include <vector>

#include "acoustics/modal/contact_impacts.h"
#include "sim/bodies/contact_record.h"
#include "sim/bodies/rigid_world.h"

namespace fluidsound::test {

inline Eigen::Vector3d eigen(const Vec3& v) { return {v[0], v[1], v[2]}; }

/// The records touching `body` (which must not move: its frame's axes are the world's), from its
/// side: the impulse on it, the normal into it, the other body's radius at the point (its local
/// point's distance from its reference) times the rolling rate as the rolling speed.
inline std::vector<acoustics::BodyContactPoint> contactsOn(const std::vector<sim::ContactRecord>& log, int body) {
  std::vector<acoustics::BodyContactPoint> points;
  for (const sim::ContactRecord& c : log) {
    if (c.bodyA != body && c.bodyB != body) continue;
    const bool isA = c.bodyA == body;
    const double sign = isA ? 1.0 : -1.0;  // the record's impulse and normal are A's
    const Eigen::Vector3d normal = sign * eigen(c.normal);
    acoustics::BodyContactPoint p;
    p.time = c.time;
    p.other = isA ? c.bodyB : c.bodyA;
    p.localPoint = eigen(isA ? c.localPointA : c.localPointB);
    p.impulse = c.normalImpulse * normal + sign * eigen(c.frictionImpulse);
    p.normalSpeed = c.normalSpeed;
    p.normalImpulse = c.normalImpulse;
    p.normal = normal;
    p.tangentialSpeed = c.tangentialSpeed;
    p.rollingSpeed = c.rollingRate * eigen(isA ? c.localPointB : c.localPointA).norm();
    points.push_back(p);
  }
  return points;
}

}  // namespace fluidsound::test
