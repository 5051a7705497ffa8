// acoustics/modal/solid_sound.cpp — see solid_sound.h.
#include "acoustics/modal/solid_sound.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <deque>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>

#include "acoustics/modal/body_contact_points.h"
#include "acoustics/modal/contact_rubbing.h"
#include "acoustics/modal/hertz_contact.h"
#include "acoustics/modal/mode_compression.h"
#include "acoustics/modal/mode_radiation.h"

namespace fluidsound::acoustics {

namespace {

/// Where a body was: its world-from-body rotation and its reference point [m].
struct BodyPlace {
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

/// A body's places by radiation window: a static body has one window.
class BodyPlaces {
 public:
  BodyPlaces(std::span<const BodyContactPoint> points, bool isStatic, double window)
      : isStatic_(isStatic), window_(window) {
    for (const BodyContactPoint& p : points) places_.try_emplace(windowOf(p.time), BodyPlace{p.orientation, p.origin});
  }
  long long windowOf(double time) const {
    return isStatic_ ? 0 : static_cast<long long>(std::floor(time / window_));
  }
  /// The place at the window's first contact, or the latest window's before it, or the first.
  const BodyPlace& at(long long window) const {
    auto it = places_.upper_bound(window);
    return it == places_.begin() ? it->second : std::prev(it)->second;
  }

 private:
  bool isStatic_;
  double window_;
  std::map<long long, BodyPlace> places_;
};

/// Gains and delay of every mode toward listener `x` [m] from a body at `place`.
struct Radiation {
  std::vector<std::complex<double>> gains;
  double delay = 0.0;
};

/// Gains and delay toward one listener, each mode's gain times its occlusion by the other bodies
/// on the straight path from the body's surface centroid.
Radiation radiationFrom(const ModalModel& model, const ModeMultipoles& multipoles, const BodyPlace& place,
                        const Eigen::Vector3d& listener, const SolidSoundSettings& s, int self) {
  const Eigen::Vector3d local = place.orientation.conjugate() * (listener - place.origin);
  Radiation r{radiationGains(model, multipoles, local, s.air), radiationDelay(multipoles, local, s.air)};
  if (!s.occluders.empty()) {
    const Eigen::Vector3d source = place.origin + place.orientation * multipoles.centre;
    const std::vector<double> factors =
        occlusionFactors(s.occluders, self, source, listener, model.frequency, s.air.soundSpeed);
    for (std::size_t j = 0; j < r.gains.size(); ++j) r.gains[j] *= factors[j];
  }
  return r;
}

void addInto(std::vector<float>& stem, const std::vector<float>& part) {
  for (std::size_t i = 0; i < stem.size() && i < part.size(); ++i) stem[i] += part[i];
}

/// The Hertz contact duration [s] of a point on body `self` at closing speed `speed`: the two
/// bodies' materials (a wall taken as `self`'s), masses and radii (static bodies and walls taken as
/// immovable and flat); 0 (an ideal impulse) when neither side moves.
double hertzDuration(const sim::ContactLog& log, std::span<const SoundingBody> bodies, int self,
                     const BodyContactPoint& point, double speed) {
  const auto& me = log.bodies[static_cast<std::size_t>(self)];
  const bool wall = point.other < 0;
  const sim::ContactLogBody* other = wall ? nullptr : &log.bodies[static_cast<std::size_t>(point.other)];
  const SolidMaterial& otherMaterial =
      wall ? bodies[static_cast<std::size_t>(self)].material : bodies[static_cast<std::size_t>(point.other)].material;
  double inverseMass = 0.0, inverseRadius = 0.0;
  if (!me.isStatic) inverseMass += 1.0 / me.mass, inverseRadius += 1.0 / me.contactRadius;
  if (other && !other->isStatic) inverseMass += 1.0 / other->mass, inverseRadius += 1.0 / other->contactRadius;
  if (!(inverseMass > 0.0) || !(speed > 0.0)) return 0.0;
  const double modulus = effectiveContactModulus(bodies[static_cast<std::size_t>(self)].material, otherMaterial);
  return hertzImpact(1.0 / inverseMass, 1.0 / inverseRadius, modulus, speed).duration;
}

/// Renders impacts (in time order) window by window into `stem`, one channel per listener.
void renderImpacts(std::span<const ModalImpact> impacts, const ModalModel& model, const ModeMultipoles& multipoles,
                   const BodyPlaces& places, const SolidSoundSettings& s, int self, const ModeGroups* groups,
                   std::vector<std::vector<float>>& stem, SolidBodyReport& report) {
  ModalSynthesisSettings synthesis{s.sampleRate, s.truncation, groups};
  std::size_t first = 0;
  while (first < impacts.size()) {
    const long long window = places.windowOf(impacts[first].time);
    std::size_t end = first;
    while (end < impacts.size() && places.windowOf(impacts[end].time) == window) ++end;
    const std::span<const ModalImpact> chunk = impacts.subspan(first, end - first);
    for (std::size_t c = 0; c < s.listeners.size(); ++c) {
      const Radiation r = radiationFrom(model, multipoles, places.at(window), s.listeners[c], s, self);
      ModalSynthesisStatistics statistics;
      addInto(stem[c], synthesizeModalImpacts(model, chunk, r.gains, s.samples, r.delay, synthesis, &statistics));
      report.oscillatorSamples += statistics.oscillatorSamples;
    }
    first = end;
  }
}

/// The rubbing forces of one body, kept alive for the ModalForce spans, by window and kind.
struct RubbingForces {
  std::deque<std::vector<Eigen::Vector3f>> samples;  ///< each chunk's forces
  std::deque<std::vector<std::size_t>> nodes;        ///< and nodes
  std::map<long long, std::vector<ModalForce>> rolling, sliding;

  /// Adds samples [begin, end) of `force` keeping only those of the kind `rolling`.
  void add(const RubbingForce& force, std::size_t begin, std::size_t end, bool rollingKind, long long window,
           double sampleRate) {
    std::vector<Eigen::Vector3f> part(force.force.begin() + std::ptrdiff_t(begin),
                                      force.force.begin() + std::ptrdiff_t(end));
    bool any = false;
    for (std::size_t i = begin; i < end; ++i) {
      if ((force.rolling[i] != 0) != rollingKind) part[i - begin].setZero();
      else any = any || !part[i - begin].isZero();
    }
    if (!any) return;
    samples.push_back(std::move(part));
    nodes.emplace_back(force.surfaceNodes.begin() + std::ptrdiff_t(begin),
                       force.surfaceNodes.begin() + std::ptrdiff_t(end));
    const ModalForce modal{force.startTime + double(begin) / sampleRate, samples.back(), nodes.back()};
    (rollingKind ? rolling : sliding)[window].push_back(modal);
  }
};

void renderForces(const std::map<long long, std::vector<ModalForce>>& byWindow, const ModalModel& model,
                  const ModeMultipoles& multipoles, const BodyPlaces& places, const SolidSoundSettings& s, int self,
                  std::vector<std::vector<float>>& stem) {
  const ModalSynthesisSettings synthesis{s.sampleRate, s.truncation, nullptr};
  for (const auto& [window, forces] : byWindow)
    for (std::size_t c = 0; c < s.listeners.size(); ++c) {
      const Radiation r = radiationFrom(model, multipoles, places.at(window), s.listeners[c], s, self);
      addInto(stem[c], synthesizeModalForces(model, forces, r.gains, s.samples, r.delay, synthesis));
    }
}

void renderBody(const sim::ContactLog& log, std::span<const SoundingBody> bodies, int b,
                const SolidSoundSettings& s, SolidStems& out) {
  const ModalModel& model = *bodies[static_cast<std::size_t>(b)].model;
  SolidBodyReport& report = out.bodies[static_cast<std::size_t>(b)];
  const std::vector<BodyContactPoint> points = bodyContactPoints(log, b);
  if (points.empty()) return;
  const ModeGroups groups = groupIndistinguishableModes(model.frequency);
  report.oscillators = s.compress ? groups.first.size() : model.frequency.size();
  const ModeMultipoles multipoles = modeMultipoles(model);
  const BodyPlaces places(points, log.bodies[static_cast<std::size_t>(b)].isStatic, s.radiationWindow);

  ImpactDetection detection = s.impacts;
  detection.substep = log.substep;
  const std::vector<ModalImpact> impacts = impactsFromContacts(
      points, model, detection,
      [&](const BodyContactPoint& p, double speed) { return hertzDuration(log, bodies, b, p, speed); });
  report.impacts = impacts.size();
  renderImpacts(impacts, model, multipoles, places, s, b, s.compress ? &groups : nullptr, out.impacts, report);

  RubbingSettings rubbing = s.rubbing;
  rubbing.sampleRate = s.sampleRate;
  rubbing.substep = log.substep;
  const RoughnessProfile surface(s.roughnessSpacing, s.roughnessSamples, s.roughnessExponent, s.roughnessShortest,
                                 s.roughnessLongest, s.roughnessSeed + static_cast<std::uint64_t>(b));
  RubbingForces forces;
  std::vector<ModalImpact> breaks;
  // Rubbing and stick–slip from the points that do not close: a closing point's impulse, its
  // friction included, is its impact's (an impact's friction released again as a slip rang the
  // board of scenes/stone_on_table 5× louder than the impact itself).
  std::vector<BodyContactPoint> touching;
  std::copy_if(points.begin(), points.end(), std::back_inserter(touching),
               [&](const BodyContactPoint& p) { return p.normalSpeed <= detection.minimumSpeed; });
  const std::vector<RubbingContact> contacts = rubbingFromContacts(touching, model, log.substep);
  report.rubbingContacts = contacts.size();
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const RubbingContact& contact = contacts[k];
    for (const RubbingSample& sample : contact.substeps) ++(sample.rolling ? report.rollingSubsteps : report.slidingSubsteps);
    const RubbingForce force = rubbingForce(contact.substeps, surface, rubbing);
    // Cut at the radiation windows: each piece heard from its window's place.
    std::size_t begin = 0;
    while (begin < force.force.size()) {
      const long long window = places.windowOf(force.startTime + double(begin) / s.sampleRate);
      std::size_t end = begin;
      while (end < force.force.size() && places.windowOf(force.startTime + double(end) / s.sampleRate) == window) ++end;
      forces.add(force, begin, end, true, window, s.sampleRate);
      forces.add(force, begin, end, false, window, s.sampleRate);
      begin = end;
    }
    StickSlipSettings stickSlip = s.stickSlip;
    stickSlip.substep = log.substep;
    stickSlip.seed = s.stickSlip.seed + 7919u * static_cast<std::uint64_t>(b) + k;
    const std::vector<ModalImpact> slips = stickSlipImpacts(contact.substeps, stickSlip);
    breaks.insert(breaks.end(), slips.begin(), slips.end());
  }
  renderForces(forces.rolling, model, multipoles, places, s, b, out.rolling);
  renderForces(forces.sliding, model, multipoles, places, s, b, out.friction);
  std::stable_sort(breaks.begin(), breaks.end(),
                   [](const ModalImpact& x, const ModalImpact& y) { return x.time < y.time; });
  report.stickSlipBreaks = breaks.size();
  renderImpacts(breaks, model, multipoles, places, s, b, s.compress ? &groups : nullptr, out.friction, report);
}

}  // namespace

SolidStems renderSolidSound(const sim::ContactLog& log, std::span<const SoundingBody> bodies,
                            const SolidSoundSettings& s, StageObserver& observer) {
  if (bodies.size() != log.bodies.size())
    throw std::invalid_argument("renderSolidSound: one sounding body per body of the contact log");
  if (!(s.sampleRate > 0.0) || !(s.radiationWindow > 0.0) || !(log.substep > 0.0))
    throw std::invalid_argument("renderSolidSound: sample rate, radiation window and substep must be > 0");
  SolidStems out;
  const std::vector<std::vector<float>> silence(s.listeners.size(), std::vector<float>(s.samples, 0.0f));
  out.impacts = out.rolling = out.friction = silence;
  out.bodies.resize(bodies.size());
  observer.started(static_cast<double>(bodies.size()));
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (observer.wasInterrupted()) throw StageInterrupted("solids body " + std::to_string(b));
    if (const ModalModel* model = bodies[b].model) {
      out.bodies[b].modes = model->frequency.size();
      if (!model->frequency.empty()) renderBody(log, bodies, static_cast<int>(b), s, out);
    }
    observer.progress(double(b + 1) / double(bodies.size()));
  }
  return out;
}

}  // namespace fluidsound::acoustics
