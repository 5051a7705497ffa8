// acoustics/transfer/frame_samples.cpp — see frame_samples.h.
#include "acoustics/transfer/frame_samples.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace fluidsound::acoustics {

std::vector<std::pair<int, FrameSamples>> samplesByFrame(const BubbleTrackSet& tracks,
                                                         const TransferSetup& setup) {
  std::map<int, FrameSamples> samplesOfFrame;
  for (std::size_t b = 0; b < tracks.bubbles.size(); ++b)
    for (std::size_t s = 0; s < tracks.bubbles[b].track.size(); ++s) {
      const double time = tracks.bubbles[b].track[s].time;
      const int frame =
          std::clamp(static_cast<int>(std::lround(time * setup.fps)), 0, setup.lastFrame);
      samplesOfFrame[frame].emplace_back(b, s);
    }
  return {samplesOfFrame.begin(), samplesOfFrame.end()};
}

void forEachFrameInChunks(const std::vector<std::pair<int, FrameSamples>>& work,
                          StageObserver& observer, const std::function<void(std::size_t)>& evaluate) {
  // Frames are independent (each sample belongs to one frame and is written by it alone), so they
  // are evaluated in parallel, a chunk at a time. An error is kept per frame and the first in
  // frame order is thrown, as a serial loop would.
  std::vector<std::exception_ptr> errors(work.size());
  observer.started(static_cast<double>(work.size()));
  for (std::size_t first = 0; first < work.size(); first += kTransferFramesPerChunk) {
    const std::size_t last = std::min(work.size(), first + kTransferFramesPerChunk);
    if (observer.wasInterrupted())
      throw StageInterrupted("transfer frame " + std::to_string(work[first].first));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t f = r.begin(); f < r.end(); ++f) {
                          try {
                            evaluate(f);
                          } catch (...) {
                            errors[f] = std::current_exception();
                          }
                        }
                      });
    for (std::size_t f = first; f < last; ++f)
      if (errors[f]) std::rethrow_exception(errors[f]);
    observer.progress(static_cast<double>(last) / work.size());
  }
}

const Vec3& samplePosition(const BubbleTrackSet& tracks, std::size_t bubble, std::size_t sample) {
  const TrackSample& s = tracks.bubbles[bubble].track[sample];
  if (!s.position)
    throw TransferInputError(
        TransferInput::Tracks,
        "bubbles[" + std::to_string(bubble) + "].track[" + std::to_string(sample) + "]",
        "a position (written by fluidsound simulate)", "none");
  return *s.position;
}

}  // namespace fluidsound::acoustics
