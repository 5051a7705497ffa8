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

std::vector<ModalImpact> impactsFromContacts(std::span<const BodyContactPoint> points, const ModalModel& model,
                                             const ImpactDetection& detection,
                                             const std::function<double(const BodyContactPoint&, double)>& contactDuration) {
  if (!(detection.substep > 0.0) || !(detection.minimumSpeed >= 0.0))
    throw std::invalid_argument("impactsFromContacts: substep > 0 and minimumSpeed >= 0");
  // The substep of each point, by its end time.
  const auto substepOf = [&](double time) { return std::llround(time / detection.substep); };
  struct Touch {
    const BodyContactPoint* first = nullptr;
    double closing = 0.0;  // the fastest closing speed of the pair's points [m/s]
    Eigen::Vector3d impulse = Eigen::Vector3d::Zero(), weightedPoint = Eigen::Vector3d::Zero();
    double weight = 0.0;
  };
  std::map<int, long long> lastClosing;  // other → the last substep it closed faster than ε
  std::vector<ModalImpact> impacts;
  for (std::size_t begin = 0; begin < points.size();) {
    const long long substep = substepOf(points[begin].time);
    std::size_t end = begin;
    std::map<int, Touch> touches;  // this substep's, by other body (ordered: deterministic)
    for (; end < points.size() && substepOf(points[end].time) == substep; ++end) {
      const BodyContactPoint& p = points[end];
      if (end > begin && p.time < points[end - 1].time)
        throw std::invalid_argument("impactsFromContacts: contact points out of time order");
      Touch& touch = touches[p.other];
      if (!touch.first) touch.first = &p;
      touch.closing = std::max(touch.closing, p.normalSpeed);
      touch.impulse += p.impulse;
      const double w = p.impulse.norm();
      touch.weightedPoint += w * p.localPoint;
      touch.weight += w;
    }
    for (const auto& [other, touch] : touches) {
      if (!(touch.closing > detection.minimumSpeed)) continue;
      const auto last = lastClosing.find(other);
      const bool fresh = last == lastClosing.end() || last->second < substep - 1;
      lastClosing[other] = substep;
      if (!fresh) continue;
      const Eigen::Vector3d where = touch.weight > 0.0 ? Eigen::Vector3d(touch.weightedPoint / touch.weight)
                                                       : touch.first->localPoint;
      impacts.push_back({touch.first->time - detection.substep, nearestSurfaceNode(model, where), touch.impulse,
                         contactDuration(*touch.first, touch.closing)});
    }
    begin = end;
  }
  return impacts;
}

}  // namespace fluidsound::acoustics
