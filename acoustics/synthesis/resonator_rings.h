// acoustics/synthesis/resonator_rings.h — the synth stage's part of a resonator's ring
// (bubble_track.h, ResonatorRing; docs/transfer.md, "The air column's ring"): each bubble's ring
// added to the listeners' channels beside the bubbles' own sound.
#pragma once

#include <cstdint>
#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/synthesis/synthesizer.h"

namespace fluidsound::acoustics {

/// @brief Adds every bubble's ring to `channels` (one per listener, at settings.sampleRate):
///        A·gain_l·e^{−β_r τ}·cos(2πf τ + phase_l) from the first sample at or after its birth
///        until it has decayed by settings.cutoffDecibels, A the bubble's free-field amplitude at
///        1 m (the oscillator model's, or the file's). A ring at or above Nyquist is left out.
///        Each ring by the exact recurrence z ← z·e^{(−β_r + 2πif)/f_s}; sequential, in bubble
///        order, so the same bits for any thread count.
/// @return the ring samples added, over all listeners
std::int64_t addResonatorRings(const BubbleTrackSet& tracks, const SynthesisSettings& settings,
                               std::vector<std::vector<float>>& channels);

}  // namespace fluidsound::acoustics
