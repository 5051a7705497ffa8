// acoustics/synthesis/head_render.cpp — see head_render.h.
#include "acoustics/synthesis/head_render.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include <tbb/parallel_invoke.h>

#include "acoustics/binaural/hrir_convolution.h"

namespace fluidsound::acoustics {

namespace {

/// The measured direction `bubble` is heard from by `head`.
std::size_t heardFrom(const BubbleTrack& bubble, std::size_t index, const ListenerHead& head,
                      const HrirTable& table) {
  for (const TrackSample& s : bubble.track) {
    if (!s.position) continue;
    const Vec3 world{(*s.position)[0] - head.position[0], (*s.position)[1] - head.position[1],
                     (*s.position)[2] - head.position[2]};
    if (world == Vec3{0.0, 0.0, 0.0}) return nearestDirection(table, {1.0, 0.0, 0.0});
    return nearestDirection(table, headDirection(world, head.facing, head.up));
  }
  throw std::invalid_argument("renderHead: bubble " + std::to_string(index) +
                              " has no track sample with a position, so no direction for head \"" +
                              head.listener + "\"");
}

/// `tracks`' bubbles `members`, each with its transfer to `listener` in channel slot[b] and 0 in
/// the others: one render gives up to kMaxListeners directions' signals at once.
BubbleTrackSet directionChannels(const BubbleTrackSet& tracks, std::size_t listener,
                                 const std::vector<std::size_t>& members,
                                 const std::vector<std::size_t>& slot, std::size_t channels) {
  BubbleTrackSet set;
  set.sampleRate = tracks.sampleRate;
  set.duration = tracks.duration;
  set.listeners.resize(channels);
  for (std::size_t c = 0; c < channels; ++c) set.listeners[c] = "direction " + std::to_string(c);
  for (std::size_t m = 0; m < members.size(); ++m) {
    BubbleTrack bubble = tracks.bubbles[members[m]];
    for (TrackSample& s : bubble.track) {
      const double t = s.transfer.empty() ? 1.0 : s.transfer[listener];
      s.transfer.assign(channels, 0.0);
      s.transfer[slot[m]] = t;
    }
    for (ResonatorRing& ring : bubble.rings) {  // heard at the head's centre, from the bubble's direction
      const double gain = ring.gain[listener], phase = ring.phase[listener];
      ring.gain.assign(channels, 0.0);
      ring.phase.assign(channels, 0.0);
      ring.gain[slot[m]] = gain;
      ring.phase[slot[m]] = phase;
    }
    set.bubbles.push_back(std::move(bubble));
  }
  return set;
}

}  // namespace

HeadSignals renderHead(const BubbleTrackSet& tracks, std::size_t listener, const ListenerHead& head,
                       const HrirTable& table, const SynthesisSettings& settings, std::int64_t frames) {
  if (table.sampleRate != settings.sampleRate)
    throw std::invalid_argument("renderHead: responses at " + std::to_string(table.sampleRate) +
                                " Hz for a render at " + std::to_string(settings.sampleRate) + " Hz");
  // Directions in order of first appearance (by bubble index): the same groups for any threads.
  std::map<std::size_t, std::size_t> groupOf;  // measured direction → group
  std::vector<std::size_t> directionOf;        // group → measured direction
  std::vector<std::size_t> groupOfBubble(tracks.bubbles.size());
  for (std::size_t b = 0; b < tracks.bubbles.size(); ++b) {
    const std::size_t d = heardFrom(tracks.bubbles[b], b, head, table);
    const auto [it, added] = groupOf.try_emplace(d, directionOf.size());
    if (added) directionOf.push_back(d);
    groupOfBubble[b] = it->second;
  }
  HeadSignals out;
  out.directions = directionOf.size();
  const std::size_t n = static_cast<std::size_t>(frames);
  std::vector<double> left(n, 0.0), right(n, 0.0);
  const double gain = freeFieldGain(table);
  const std::size_t perRender = static_cast<std::size_t>(kMaxListeners);
  for (std::size_t first = 0; first < directionOf.size(); first += perRender) {
    const std::size_t channels = std::min(perRender, directionOf.size() - first);
    std::vector<std::size_t> members, slot;
    for (std::size_t b = 0; b < tracks.bubbles.size(); ++b) {
      const std::size_t g = groupOfBubble[b];
      if (g >= first && g < first + channels) members.push_back(b), slot.push_back(g - first);
    }
    SynthesisResult rendered =
        synthesize(directionChannels(tracks, listener, members, slot, channels), settings);
    out.oscillatorSamples += rendered.report.oscillatorSamples;
    for (std::size_t c = 0; c < channels; ++c) {
      std::vector<float>& signal = rendered.channels[c];
      signal.resize(n, 0.0f);  // a render of fewer bubbles may end sooner
      const std::size_t d = directionOf[first + c];
      const auto ear = [&](const std::vector<float>& response, double delay, std::vector<double>& into) {
        addConvolution(signal, response, static_cast<std::size_t>(std::lround(std::max(0.0, delay) * table.sampleRate)),
                       gain, into);
      };
      // Each ear sums its directions in the same order whatever the thread count.
      tbb::parallel_invoke([&] { ear(table.left[d], table.delayLeft[d], left); },
                           [&] { ear(table.right[d], table.delayRight[d], right); });
    }
  }
  out.left.assign(left.begin(), left.end());
  out.right.assign(right.begin(), right.end());
  return out;
}

}  // namespace fluidsound::acoustics
