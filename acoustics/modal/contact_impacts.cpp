// acoustics/modal/contact_impacts.cpp — see contact_impacts.h.
#include "acoustics/modal/contact_impacts.h"

#include <cmath>
#include <map>
#include <stdexcept>

namespace fluidsound::acoustics {

std::size_t nearestSurfaceNode(const ModalModel& model, const Eigen::Vector3d& point) {
  if (model.surfacePositions.empty()) throw std::invalid_argument("nearestSurfaceNode: the model has no surface");
  std::size_t best = 0;
  double bestDistance = (model.surfacePositions[0] - point).squaredNorm();
  for (std::size_t s = 1; s < model.surfacePositions.size(); ++s) {
    const double d = (model.surfacePositions[s] - point).squaredNorm();
    if (d < bestDistance) best = s, bestDistance = d;
  }
  return best;
}

std::vector<SubstepTouch> substepTouches(std::span<const BodyContactPoint> points, double substep) {
  if (!(substep > 0.0)) throw std::invalid_argument("substepTouches: the substep must be > 0");
  std::vector<SubstepTouch> touches;
  for (std::size_t begin = 0; begin < points.size();) {
    const long long step = std::llround(points[begin].time / substep);
    std::map<int, SubstepTouch> byOther;  // ordered: deterministic
    std::size_t end = begin;
    for (; end < points.size() && std::llround(points[end].time / substep) == step; ++end) {
      if (end > begin && points[end].time < points[end - 1].time)
        throw std::invalid_argument("substepTouches: contact points out of time order");
      SubstepTouch& touch = byOther[points[end].other];
      touch.substep = step, touch.other = points[end].other;
      touch.points.push_back(&points[end]);
    }
    if (end < points.size() && points[end].time < points[end - 1].time)
      throw std::invalid_argument("substepTouches: contact points out of time order");
    for (auto& [other, touch] : byOther) touches.push_back(std::move(touch));
    begin = end;
  }
  return touches;
}

std::vector<ModalImpact> impactsFromContacts(std::span<const BodyContactPoint> points, const ModalModel& model,
                                             const ImpactDetection& detection,
                                             const std::function<double(const BodyContactPoint&, double)>& contactDuration) {
  if (!(detection.minimumSpeed >= 0.0)) throw std::invalid_argument("impactsFromContacts: minimumSpeed >= 0");
  std::map<int, long long> lastClosing;  // other → the last substep it closed faster than ε
  std::vector<ModalImpact> impacts;
  for (const SubstepTouch& touch : substepTouches(points, detection.substep)) {
    double closing = 0.0, weight = 0.0;  // the fastest closing speed of the pair's points [m/s]
    Eigen::Vector3d impulse = Eigen::Vector3d::Zero(), weightedPoint = Eigen::Vector3d::Zero();
    for (const BodyContactPoint* p : touch.points) {
      closing = std::max(closing, p->normalSpeed);
      impulse += p->impulse;
      weightedPoint += p->impulse.norm() * p->localPoint;
      weight += p->impulse.norm();
    }
    if (!(closing > detection.minimumSpeed)) continue;
    const auto last = lastClosing.find(touch.other);
    const bool fresh = last == lastClosing.end() || last->second < touch.substep - 1;
    lastClosing[touch.other] = touch.substep;
    if (!fresh) continue;
    const BodyContactPoint& first = *touch.points.front();
    const Eigen::Vector3d where = weight > 0.0 ? Eigen::Vector3d(weightedPoint / weight) : first.localPoint;
    impacts.push_back({first.time - detection.substep, nearestSurfaceNode(model, where), impulse,
                       contactDuration(first, closing)});
  }
  return impacts;
}

}  // namespace fluidsound::acoustics
