// io/bubble_histories.cpp — see bubble_histories.h.
#include "io/bubble_histories.h"

#include <filesystem>

namespace fluidsound::io {

acoustics::BubbleTrackSet bubbleTracksFromHistories(std::span<const sim::BubbleHistory> bubbles,
                                                    const sim::Scene& scene) {
  acoustics::BubbleTrackSet set;
  set.sampleRate = scene.sampleRate;
  set.duration = scene.time.duration;
  for (const sim::Listener& l : scene.listeners) {
    set.listeners.push_back(l.name);
    if (l.head) set.heads.push_back({l.name, l.position, l.head->facing, l.head->up});
  }
  // Absolute, so that the bubble file names the same set wherever it is read from.
  if (scene.hrtf) set.hrtf = std::filesystem::absolute(*scene.hrtf).lexically_normal().string();
  set.bubbles.reserve(bubbles.size());
  for (const sim::BubbleHistory& b : bubbles) {
    acoustics::BubbleTrack track;
    track.radius = b.radius;
    track.birth = b.birth;
    for (const sim::BubbleSample& s : b.samples) {
      if (!track.track.empty() && s.time <= track.track.back().time) continue;
      acoustics::TrackSample sample;
      sample.time = s.time;
      sample.depth = s.depth;
      sample.position = s.position;
      track.track.push_back(sample);
    }
    set.bubbles.push_back(std::move(track));
  }
  return set;
}

}  // namespace fluidsound::io
