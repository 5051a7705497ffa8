// acoustics/synthesis/synthesis_voice.h — the synthesizer's bubbles prepared for rendering
// ("voices"), their state at block boundaries and their oscillator parameters over one block: the
// part of synthesis shared by the renderer (synthesizer.cpp) and its plain reference
// (synthesizer_reference.h). Internal to acoustics/synthesis.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/bubble/instantaneous_frequency.h"
#include "acoustics/synthesis/oscillator_bank.h"
#include "acoustics/synthesis/synthesizer.h"
#include "acoustics/synthesis/track_interpolation.h"

namespace fluidsound::acoustics {

/// A bubble prepared for rendering: its constants, its track and the samples it occupies.
struct Voice {
  RingingBubble ringing;  ///< R, t_b, deep constants (instantaneous_frequency.h)
  TrackInterpolator track;
  double sampleDecay = 0.0;      ///< e^{−βΔt}
  double blockDecay = 0.0;       ///< e^{−βBΔt}, B = kBlockSamples
  std::int64_t firstSample = 0;  ///< first sample at or after birth
  std::int64_t firstBlock = 0;
  double endTime = 0.0;        ///< time it has decayed by the cut-off [s]
  std::int64_t endSample = 0;  ///< first sample after endTime
  std::int64_t endBlock = 0;   ///< one past the block that holds endSample − 1
};

/// Where a voice stands at a given sample.
struct VoiceState {
  std::int64_t sample = 0;
  double phase = 0.0;             ///< φ [rad], in [0, 2π)
  double magnitude = 0.0;         ///< A e^{−β(t−t_b)} [Pa]
  double angularFrequency = 0.0;  ///< instantaneous ω [rad/s]
  TrackValues values;             ///< depth and transfer per listener
  std::size_t cursor = 0;         ///< track interval of the last evaluation
};

/// Everything a block needs about the whole render.
struct RenderContext {
  const SynthesisSettings& settings;
  OscillatorKernel kernel;
  std::size_t channels;
  double dt;  ///< sample period [s]
  std::int64_t frames;
};

/// The voices of a render, and the memory their tracks read.
struct VoiceSet {
  std::unique_ptr<double[]> trackStorage;  ///< every voice's track tables, in render order
  std::vector<Voice> voices;  ///< by first sample (ties in file order); none aliased or silent
  std::int64_t frames = 0;    ///< samples per channel
  std::int64_t maxLifetimeBlocks = 0;  ///< the most blocks from a voice's first to its end
  /// prepareVoices' work arrays, per bubble in render order. Kept with the voices until the
  /// render ends, as when they were locals of synthesize: freed between preparing and rendering
  /// (each ≥ 64 kB for 10⁴ bubbles), they let the allocator hand memory back to the system and
  /// fault it in again during the render (BM_Synthesize/10000: 25 % more CPU time).
  struct Preparation {
    std::vector<std::pair<std::int64_t, std::size_t>> order;  ///< (first sample, bubble index)
    std::vector<std::size_t> trackOffset;  ///< each voice's track tables in trackStorage
    std::vector<char> aliased;             ///< peak frequency ≥ Nyquist
    std::vector<std::int64_t> clamped;     ///< track samples shallower than 1.25 R
  } preparation;
};

/// @brief Every bubble of `tracks` as a voice, in render order, without those whose peak
///        frequency reaches Nyquist or that are born after the end; fills the report's counts
///        (depthsClamped, bubblesAboveNyquist, bubblesSilent, bubblesRendered, frames,
///        oscillatorSamples). Parallel, the same for any thread count.
VoiceSet prepareVoices(const BubbleTrackSet& tracks, const SynthesisSettings& settings,
                       SynthesisReport& report);

/// A voice at its first sample.
VoiceState startVoice(const Voice& voice, const RenderContext& ctx);

/// @brief The state of a voice at `sample` (the next block boundary) from its state `st`, with ω
///        varying linearly per sample: φ += Δt(Nω_a + Δω N(N−1)/2), Δω = (ω_b − ω_a)/N — exactly
///        what the oscillator recurrence does (docs/synthesis.md).
VoiceState advanceVoice(const Voice& voice, const VoiceState& st, std::int64_t sample,
                        const RenderContext& ctx);

/// One voice's oscillator over one block, as the kernels take it (OscillatorGroup, one lane).
struct OscillatorLane {
  float zRe, zIm;                 ///< complex pressure at the first sample [Pa]
  float rRe, rIm;                 ///< per-sample factor e^{(−β+iω)Δt}
  float cRe, cIm;                 ///< per-sample change of r, e^{iΔωΔt}
  float firstSample;              ///< offset in the block of the first sample
  float gain[kMaxListeners];      ///< transfer at the first sample, per listener [-]
  float gainStep[kMaxListeners];  ///< its change per sample [-]
};

/// The oscillator of a voice from state `st` to `next` (its state at the block's end).
OscillatorLane oscillatorLane(const Voice& voice, const VoiceState& st, const VoiceState& next,
                              const RenderContext& ctx);

}  // namespace fluidsound::acoustics
