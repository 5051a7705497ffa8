// acoustics/synthesis/synthesizer_reference.h — the synthesizer's rendering written plainly: block
// after block over the whole clip on one thread, each voice's oscillator over the block an
// unpacked OscillatorLane, run by the scalar reference of the oscillator loop. The specification
// the packed, segmented, parallel renderer is tested against
// (tests/acoustics/synthesis/synthesizer_reference_test.cpp). Not used for rendering.
#pragma once

#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/synthesis/synthesizer.h"

namespace fluidsound::acoustics {

/// @brief synthesize(tracks, settings).channels with the baseline kernel (the scalar reference
///        loop gives the baseline's bits; the fusing kernels differ in the last bits): the same
///        voices (prepareVoices), each brought from block to block by the same steps, its lanes
///        of each block (those ringing through it first, then those born inside it) run 16 to a
///        group, and the 16 lane sums of each sample added by the pairwise tree
///        ((l_i + l_{i+8}) + (… + …)), as sumOscillatorLanes adds them. settings.kernel is ignored.
/// @return pressure [Pa] per listener
std::vector<std::vector<float>> synthesizeReference(const BubbleTrackSet& tracks,
                                                    const SynthesisSettings& settings);

}  // namespace fluidsound::acoustics
