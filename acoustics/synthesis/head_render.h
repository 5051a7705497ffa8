// acoustics/synthesis/head_render.h — a binaural head's two channels (docs/binaural.md): each
// bubble's pressure at the head's centre (its transfer to the head), filtered by the measured
// head-related impulse responses of the direction it is heard from. Bubbles heard from the same
// measured direction are rendered together into one signal (a virtual loudspeaker at that
// direction), which is convolved with that direction's pair, so the ears get the set's full
// interaural time and level differences at every frequency, not only at the bubble's own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "acoustics/binaural/hrir_table.h"
#include "acoustics/bubble/bubble_track.h"
#include "acoustics/synthesis/synthesizer.h"

namespace fluidsound::acoustics {

/// A head's two ears, and what it took.
struct HeadSignals {
  std::vector<float> left, right;    ///< pressure at each ear [Pa]
  std::size_t directions = 0;        ///< measured directions the bubbles were heard from
  std::int64_t oscillatorSamples = 0;  ///< of the renders per direction
};

/// @brief The ears of `head`, listener `listener` of `tracks`, over `frames` samples at
///        settings.sampleRate. A bubble is heard from the direction of its first track sample
///        with a position, seen from the head's centre in the head's frame, rounded to the
///        nearest measured direction (the set's spacing: 5–10° for KEMAR); it is rendered by
///        synthesize() with its transfer to the head's centre and convolved with that direction's
///        responses, scaled by freeFieldGain(table) and delayed by the set's delays (whole samples).
/// @param table  responses at settings.sampleRate (io::readHrirTable resamples)
/// @throws std::invalid_argument if a bubble has no positioned track sample, the table's rate is
///         not settings.sampleRate, or as synthesize()
/// @note Bit-identical for any thread count.
HeadSignals renderHead(const BubbleTrackSet& tracks, std::size_t listener, const ListenerHead& head,
                       const HrirTable& table, const SynthesisSettings& settings, std::int64_t frames);

}  // namespace fluidsound::acoustics
