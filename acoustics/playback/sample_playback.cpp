// acoustics/playback/sample_playback.cpp — see sample_playback.h.
#include "acoustics/playback/sample_playback.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fluidsound::acoustics {
namespace {

double amplitudeOf(double gainDb) { return std::pow(10.0, gainDb / 20.0); }

}  // namespace

std::vector<float> playImpacts(const RecordedSound& sound, std::span<const ImpactTrigger> impacts, std::size_t samples,
                               double minimumInterval) {
  if (!(sound.sampleRate > 0.0) || !(minimumInterval >= 0.0))
    throw std::invalid_argument("playImpacts: sample rate > 0 and minimum interval >= 0");
  std::vector<float> out(samples, 0.0f);
  double lastTime = -1e300, lastGain = -1e300;
  for (const ImpactTrigger& impact : impacts) {
    if (impact.time - lastTime < minimumInterval && impact.gainDb <= lastGain) continue;
    lastTime = impact.time, lastGain = impact.gainDb;
    const auto first = static_cast<long long>(std::llround(impact.time * sound.sampleRate));
    const auto gain = static_cast<float>(amplitudeOf(impact.gainDb));
    for (std::size_t i = 0; i < sound.samples.size(); ++i) {
      const long long n = first + static_cast<long long>(i);
      if (n < 0) continue;
      if (n >= static_cast<long long>(samples)) break;
      out[static_cast<std::size_t>(n)] += gain * sound.samples[i];
    }
  }
  return out;
}

std::vector<float> playLoop(const RecordedSound& sound, std::span<const LoopSubstep> substeps, double substep,
                            std::size_t samples, double fade) {
  if (!(sound.sampleRate > 0.0) || !(substep > 0.0) || !(fade >= 0.0) || sound.samples.empty())
    throw std::invalid_argument("playLoop: a recording, sample rate and substep > 0, fade >= 0");
  std::vector<float> out(samples, 0.0f);
  if (substeps.empty()) return out;
  const double dt = 1.0 / sound.sampleRate, start = substeps.front().time - substep;
  const double fadeStep = fade > 0.0 ? dt / fade : 1.0;
  double envelope = 0.0;    // the fade: 0 silent … 1 playing
  std::size_t position = 0;  // in the recording
  for (std::size_t n = 0; n < samples; ++n) {
    const double t = (static_cast<double>(n) + 0.5) * dt;
    if (t < start) continue;
    const auto k = static_cast<std::size_t>((t - start) / substep);
    if (k >= substeps.size() && envelope == 0.0) break;
    const LoopSubstep& now = substeps[std::min(k, substeps.size() - 1)];
    const bool playing = k < substeps.size() && now.active;
    if (playing && envelope == 0.0) position = 0;  // a new start plays the loop from its beginning
    envelope = std::clamp(envelope + (playing ? fadeStep : -fadeStep), 0.0, 1.0);
    if (envelope == 0.0) continue;
    // Gain linear between the substeps' midpoints (held at the ends, and while fading out).
    const double mid = (t - start) / substep - 0.5;
    const auto a = static_cast<std::size_t>(std::clamp(std::floor(mid), 0.0, static_cast<double>(substeps.size() - 1)));
    const std::size_t b = std::min(a + 1, substeps.size() - 1);
    const double u = std::clamp(mid - static_cast<double>(a), 0.0, 1.0);
    const double gainDb = substeps[a].gainDb + u * (substeps[b].gainDb - substeps[a].gainDb);
    out[n] = static_cast<float>(envelope * amplitudeOf(gainDb) * sound.samples[position]);
    position = (position + 1) % sound.samples.size();
  }
  return out;
}

}  // namespace fluidsound::acoustics
