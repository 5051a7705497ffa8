// acoustics/transfer/frame_samples.h — the transfer stage's work list, shared by its models: the
// track samples of every frame that has any, in frame order, so that each frame is opened once;
// and the frame-chunked parallel loop both models run over it (thread-count independent).
#pragma once

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/transfer/transfer_stage.h"

namespace fluidsound::acoustics {

/// (bubble, sample) indices of the samples of one frame.
using FrameSamples = std::vector<std::pair<std::size_t, std::size_t>>;

/// The samples of every frame that has any, in frame order: the sample at time t belongs to
/// frame round(t·fps) clamped to 0 … lastFrame.
std::vector<std::pair<int, FrameSamples>> samplesByFrame(const BubbleTrackSet& tracks,
                                                         const TransferSetup& setup);

/// @brief Calls evaluate(f) for every f in work's index range, kTransferFramesPerChunk frames in
///        parallel at a time: observer.started(frames) first, observer.wasInterrupted() before and
///        observer.progress() after each chunk; of several failing frames the first in frame
///        order's error is rethrown.
/// @throws StageInterrupted("transfer frame F") when the observer asks to stop before frame F
void forEachFrameInChunks(const std::vector<std::pair<int, FrameSamples>>& work,
                          StageObserver& observer, const std::function<void(std::size_t)>& evaluate);

/// The sample's position or a TransferInputError naming it ("bubbles[B].track[S]").
const Vec3& samplePosition(const BubbleTrackSet& tracks, std::size_t bubble, std::size_t sample);

}  // namespace fluidsound::acoustics
