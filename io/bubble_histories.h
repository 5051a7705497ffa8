// io/bubble_histories.h — the bubble model's output (sim::BubbleHistory) as the bubble tracks of
// `fluidsound.bubbles/1` (DESIGN.md): the file `simulate` writes for the transfer stage.
#pragma once

#include <span>

#include "acoustics/bubble/bubble_track.h"
#include "sim/bubbles/bubble_history.h"
#include "sim/scene.h"

namespace fluidsound::io {

/// @brief One track per bubble: radius, birth, and per sample its time, depth and position; no
///        transfer yet (the transfer stage fills it). The scene gives the listeners' names, the
///        sample rate and the duration. A sample at the same time as the one before it is dropped
///        (a bubble born exactly on a frame).
acoustics::BubbleTrackSet bubbleTracksFromHistories(std::span<const sim::BubbleHistory> bubbles,
                                                    const sim::Scene& scene);

}  // namespace fluidsound::io
