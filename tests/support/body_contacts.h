// tests/support/body_contacts.h — a RigidWorld's contact log as one body's contact points
// (acoustics::bodyContactPoints, as `run` reads them from contacts.bin), for tests that step a
// world in memory.
#pragma once

#include <vector>

#include "acoustics/modal/body_contact_points.h"
#include "sim/bodies/rigid_world.h"

namespace fluidsound::test {

/// The world's contact log so far with its bodies, as simulate writes it.
inline sim::ContactLog contactLogOf(const sim::RigidWorld& world) {
  sim::ContactLog log;
  log.substep = world.substep();
  log.duration = world.time();
  for (int b = 0; b < world.bodyCount(); ++b)
    log.bodies.push_back({world.spec(b).name, world.mass(b), world.spec(b).isStatic, 1.0});
  log.records = world.contacts();
  return log;
}

/// The points of the world's log that touch `body`, from its side, in its frame.
inline std::vector<acoustics::BodyContactPoint> contactsOn(const sim::RigidWorld& world, int body) {
  return acoustics::bodyContactPoints(contactLogOf(world), body);
}

}  // namespace fluidsound::test
