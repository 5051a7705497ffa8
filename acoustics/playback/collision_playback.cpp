// acoustics/playback/collision_playback.cpp — see collision_playback.h.
#include "acoustics/playback/collision_playback.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "acoustics/playback/collision_loudness.h"
#include "sim/core/vec3_math.h"

namespace fluidsound::acoustics {
namespace {

/// One substep of one pair: its points summed.
struct PairSubstep {
  long long substep = 0;
  double normalImpulse = 0.0;    ///< Σ J_n [N·s]
  double frictionImpulse = 0.0;  ///< |Σ J_t| [N·s]
  double closingSpeed = 0.0;     ///< the largest of its points' [m/s]
  double slidingSpeed = 0.0, rollingRate = 0.0;  ///< the largest of its points' [m/s], [rad/s]
  double rollingSpeed = 0.0;     ///< rolling rate × the rolling body's radius at the point [m/s]
  std::array<double, 3> position{};  ///< of its first point [m]
};

/// The log's records by pair (ascending), each pair's substeps in time order.
std::map<std::pair<int, int>, std::vector<PairSubstep>> pairSubsteps(const sim::ContactLog& log) {
  std::map<std::pair<int, int>, std::vector<PairSubstep>> pairs;
  std::map<std::pair<int, int>, Vec3> friction;  // the current substep's Σ J_t per pair
  for (const sim::ContactRecord& c : log.records) {
    const std::pair<int, int> key{c.bodyA, c.bodyB};
    const auto substep = static_cast<long long>(std::llround(c.time / log.substep));
    std::vector<PairSubstep>& steps = pairs[key];
    if (steps.empty() || steps.back().substep != substep) {
      steps.push_back({substep});
      steps.back().position = {c.position[0], c.position[1], c.position[2]};
      friction[key] = {};
    }
    PairSubstep& s = steps.back();
    Vec3& f = friction[key];
    for (int a = 0; a < 3; ++a) f[a] += c.frictionImpulse[a];
    s.normalImpulse += c.normalImpulse;
    s.frictionImpulse = norm(f);
    s.closingSpeed = std::max(s.closingSpeed, c.normalSpeed);
    s.slidingSpeed = std::max(s.slidingSpeed, c.tangentialSpeed);
    s.rollingRate = std::max(s.rollingRate, c.rollingRate);
    const bool bMoves = c.bodyB >= 0 && !log.bodies[static_cast<std::size_t>(c.bodyB)].isStatic;
    s.rollingSpeed = std::max(s.rollingSpeed, c.rollingRate * norm(bMoves ? c.localPointB : c.localPointA));
  }
  return pairs;
}

double massOf(const sim::ContactLog& log, int body) {
  return body < 0 ? 0.0 : log.bodies[static_cast<std::size_t>(body)].mass;  // 0: immovable
}

}  // namespace

PlaybackStems renderCollisionPlayback(const sim::ContactLog& log,
                                      const std::function<const CollisionRecordings*(int, int)>& recordingsOf,
                                      const CollisionPlaybackSettings& s) {
  if (!(s.sampleRate > 0.0) || !(s.soundSpeed > 0.0) || !(s.nearest > 0.0) || !(log.substep > 0.0))
    throw std::invalid_argument("renderCollisionPlayback: sample rate, sound speed, nearest distance and substep > 0");
  const std::vector<std::vector<float>> silence(s.listeners.size(), std::vector<float>(s.samples, 0.0f));
  PlaybackStems out{silence, silence, silence};
  const double dt = log.substep;
  for (const auto& entry : pairSubsteps(log)) {
    // (named references, not a structured binding: clang 14, the fuzz build's, cannot capture one)
    const std::pair<int, int>& pair = entry.first;
    const std::vector<PairSubstep>& steps = entry.second;
    const CollisionRecordings* recordings = recordingsOf(pair.first, pair.second);
    if (!recordings) continue;
    for (const RecordedSound* sound : {&recordings->impact, &recordings->slide, &recordings->roll})
      if (!sound->samples.empty() && sound->sampleRate != s.sampleRate)
        throw std::invalid_argument("renderCollisionPlayback: a recording at " + std::to_string(sound->sampleRate) +
                                    " Hz, the output's is " + std::to_string(s.sampleRate) + " Hz");
    const double mass = reducedMass(massOf(log, pair.first), massOf(log, pair.second));
    // Impacts: closing faster than the threshold after a substep that did not; the pair's loudest
    // (largest v·√m, the same m throughout) is the recording's level.
    std::vector<const PairSubstep*> impacts;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const bool before = k > 0 && steps[k - 1].substep == steps[k].substep - 1 &&
                          steps[k - 1].closingSpeed > s.impactSpeed;
      if (steps[k].closingSpeed > s.impactSpeed && !before) impacts.push_back(&steps[k]);
    }
    double loudestImpact = 0.0, loudestSlide = 0.0, loudestRoll = 0.0;
    for (const PairSubstep* i : impacts) loudestImpact = std::max(loudestImpact, i->closingSpeed);
    const auto sliding = [&](const PairSubstep& p) {
      return p.frictionImpulse / dt >= s.slideForce && p.rollingSpeed <= p.slidingSpeed;
    };
    const auto rolling = [&](const PairSubstep& p) { return p.rollingSpeed > p.slidingSpeed && p.rollingRate > s.rollRate; };
    for (const PairSubstep& p : steps) {
      if (sliding(p)) loudestSlide = std::max(loudestSlide, p.normalImpulse / dt * p.slidingSpeed);
      if (rolling(p)) loudestRoll = std::max(loudestRoll, p.normalImpulse / dt * p.rollingRate);
    }
    for (std::size_t c = 0; c < s.listeners.size(); ++c) {
      const auto spread = [&](const std::array<double, 3>& at) {  // [dB] and delay [s]
        const double r = norm(sub(at, s.listeners[c]));
        return std::pair{20.0 * std::log10(1.0 / std::max(r, s.nearest)), r / s.soundSpeed};
      };
      const double level = 20.0 * std::log10(recordings->peakPascals);
      if (!recordings->impact.samples.empty() && !impacts.empty()) {
        std::vector<ImpactTrigger> triggers;
        for (const PairSubstep* i : impacts) {
          const auto [db, delay] = spread(i->position);
          triggers.push_back({double(i->substep - 1) * dt + delay,
                              level + db + impactGainDb(i->closingSpeed, std::max(mass, 1e-300), loudestImpact,
                                                        std::max(mass, 1e-300))});
        }
        std::stable_sort(triggers.begin(), triggers.end(),
                         [](const ImpactTrigger& a, const ImpactTrigger& b) { return a.time < b.time; });
        const std::vector<float> played = playImpacts(recordings->impact, triggers, s.samples);
        for (std::size_t n = 0; n < s.samples; ++n) out.impacts[c][n] += played[n];
        if (c == 0) out.impactsPlayed += triggers.size();
      }
      // Loops over every substep from the pair's first to its last, silent where it does not rub;
      // heard from the first substep's place (its delay fixed for the loop).
      const auto loop = [&](const RecordedSound& sound, auto&& active, double loudest, std::vector<float>& stem,
                            bool isRoll, std::size_t& count) {
        if (sound.samples.empty() || !(loudest > 0.0)) return;
        const long long first = steps.front().substep, last = steps.back().substep;
        std::vector<LoopSubstep> substeps(static_cast<std::size_t>(last - first + 1));
        const double delay = spread(steps.front().position).second;
        for (std::size_t k = 0; k < substeps.size(); ++k)
          substeps[k].time = double(first + static_cast<long long>(k)) * dt + delay;
        for (const PairSubstep& p : steps) {
          if (!active(p)) continue;
          LoopSubstep& l = substeps[static_cast<std::size_t>(p.substep - first)];
          const double speed = isRoll ? p.rollingRate : p.slidingSpeed;
          l.active = true;
          // Against the pair's loudest power P₀ = max F_n·v: the reference F₀·v₀ = 1 N × P₀.
          l.gainDb = level + spread(p.position).first + rubbingGainDb(p.normalImpulse / dt, speed, 1.0, loudest);
          if (c == 0) ++count;
        }
        const std::vector<float> played = playLoop(sound, substeps, dt, s.samples);
        for (std::size_t n = 0; n < s.samples; ++n) stem[n] += played[n];
      };
      loop(recordings->slide, sliding, loudestSlide, out.friction[c], false, out.slideSubsteps);
      loop(recordings->roll, rolling, loudestRoll, out.rolling[c], true, out.rollSubsteps);
    }
  }
  return out;
}

}  // namespace fluidsound::acoustics
