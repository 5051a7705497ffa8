// acoustics/modal/contact_rubbing.cpp — see contact_rubbing.h.
#include "acoustics/modal/contact_rubbing.h"

#include <cmath>
#include <map>
#include <stdexcept>

namespace fluidsound::acoustics {

std::vector<RubbingContact> rubbingFromContacts(std::span<const BodyContactPoint> points, const ModalModel& model,
                                                double substep) {
  struct Open {
    long long lastSubstep = 0;
    std::size_t index = 0;  // into the result
  };
  std::vector<RubbingContact> contacts;
  std::map<int, Open> open;  // other → its touch still running
  for (const SubstepTouch& touch : substepTouches(points, substep)) {
    double impulse = 0.0, sliding = 0.0, rolling = 0.0;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero(), point = Eigen::Vector3d::Zero();
    Eigen::Vector3d friction = Eigen::Vector3d::Zero();  // Σ of the points' friction impulses [N·s]
    for (const BodyContactPoint* p : touch.points) {
      impulse += p->normalImpulse;
      sliding += p->normalImpulse * p->tangentialSpeed;
      rolling += p->normalImpulse * p->rollingSpeed;
      normal += p->normalImpulse * p->normal;
      point += p->normalImpulse * p->localPoint;
      friction += p->impulse - p->normalImpulse * p->normal;
    }
    const BodyContactPoint& first = *touch.points.front();
    const double w = impulse > 0.0 ? 1.0 / impulse : 0.0;
    RubbingSample sample;
    sample.time = touch.points.back()->time;
    sample.normalForce = impulse / substep;
    sample.friction = friction / substep;
    sample.speed = (sliding + rolling) * w;
    sample.rolling = rolling > sliding;
    sample.normal = normal.norm() > 0.0 ? Eigen::Vector3d(normal.normalized()) : first.normal;
    sample.surfaceNode = nearestSurfaceNode(model, impulse > 0.0 ? Eigen::Vector3d(point * w) : first.localPoint);
    const auto running = open.find(touch.other);
    if (running == open.end() || running->second.lastSubstep != touch.substep - 1) {
      open[touch.other] = {touch.substep, contacts.size()};
      contacts.push_back({touch.other, {}});
    } else {
      running->second.lastSubstep = touch.substep;
    }
    contacts[open[touch.other].index].substeps.push_back(sample);
  }
  return contacts;
}

}  // namespace fluidsound::acoustics
