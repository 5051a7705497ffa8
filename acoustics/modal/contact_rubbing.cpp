// acoustics/modal/contact_rubbing.cpp — see contact_rubbing.h.
#include "acoustics/modal/contact_rubbing.h"

#include <cmath>
#include <map>
#include <stdexcept>

namespace fluidsound::acoustics {

std::vector<RubbingContact> rubbingFromContacts(std::span<const BodyContactPoint> points, const ModalModel& model,
                                                double substep) {
  if (!(substep > 0.0)) throw std::invalid_argument("rubbingFromContacts: substep must be > 0");
  struct Sum {
    double time = 0.0, impulse = 0.0, sliding = 0.0, rolling = 0.0;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero(), point = Eigen::Vector3d::Zero(), anyPoint, anyNormal;
    Eigen::Vector3d friction = Eigen::Vector3d::Zero();  // Σ of the points' friction impulses [N·s]
  };
  struct Open {
    long long lastSubstep = 0;
    std::size_t index = 0;  // into the result
  };
  std::vector<RubbingContact> contacts;
  std::map<int, Open> open;  // other → its touch still running
  for (std::size_t begin = 0; begin < points.size();) {
    const long long step = std::llround(points[begin].time / substep);
    std::map<int, Sum> sums;  // this substep's, by other body (ordered: deterministic)
    std::size_t end = begin;
    for (; end < points.size() && std::llround(points[end].time / substep) == step; ++end) {
      const BodyContactPoint& p = points[end];
      Sum& sum = sums[p.other];
      if (sum.impulse == 0.0) sum.anyPoint = p.localPoint, sum.anyNormal = p.normal;
      sum.time = p.time;
      sum.impulse += p.normalImpulse;
      sum.sliding += p.normalImpulse * p.tangentialSpeed;
      sum.rolling += p.normalImpulse * p.rollingSpeed;
      sum.normal += p.normalImpulse * p.normal;
      sum.point += p.normalImpulse * p.localPoint;
      sum.friction += p.impulse - p.normalImpulse * p.normal;
    }
    for (const auto& [other, sum] : sums) {
      RubbingSample sample;
      sample.time = sum.time;
      sample.normalForce = sum.impulse / substep;
      sample.friction = sum.friction / substep;
      const double w = sum.impulse > 0.0 ? 1.0 / sum.impulse : 0.0;
      const double sliding = sum.sliding * w, rolling = sum.rolling * w;
      sample.speed = sliding + rolling;
      sample.rolling = rolling > sliding;
      sample.normal = sum.normal.norm() > 0.0 ? Eigen::Vector3d(sum.normal.normalized()) : sum.anyNormal;
      sample.surfaceNode = nearestSurfaceNode(model, sum.impulse > 0.0 ? Eigen::Vector3d(sum.point * w) : sum.anyPoint);
      const auto running = open.find(other);
      if (running == open.end() || running->second.lastSubstep != step - 1) {
        open[other] = {step, contacts.size()};
        contacts.push_back({other, {}});
      } else {
        running->second.lastSubstep = step;
      }
      contacts[open[other].index].substeps.push_back(sample);
    }
    begin = end;
  }
  return contacts;
}

}  // namespace fluidsound::acoustics
