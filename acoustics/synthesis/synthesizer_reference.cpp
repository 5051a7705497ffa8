// acoustics/synthesis/synthesizer_reference.cpp — see synthesizer_reference.h.
#include "acoustics/synthesis/resonator_rings.h"
#include "acoustics/synthesis/synthesizer_reference.h"

#include <algorithm>
#include <cstdint>

#include "acoustics/synthesis/oscillator_bank.h"
#include "acoustics/synthesis/oscillator_bank_reference.h"
#include "acoustics/synthesis/synthesis_voice.h"

namespace fluidsound::acoustics {

namespace {

/// Adds the lanes into the accumulator, lane q in slot q mod 16 of its group of 16.
void accumulateLanes(const std::vector<OscillatorLane>& lanes, bool masked, std::size_t channels,
                     float* accumulator) {
  for (std::size_t first = 0; first < lanes.size(); first += kOscillatorLanes) {
    OscillatorGroup g{};
    const std::size_t used = std::min<std::size_t>(kOscillatorLanes, lanes.size() - first);
    for (std::size_t slot = 0; slot < used; ++slot) {
      const OscillatorLane& lane = lanes[first + slot];
      g.zRe[slot] = lane.zRe, g.zIm[slot] = lane.zIm;
      g.rRe[slot] = lane.rRe, g.rIm[slot] = lane.rIm;
      g.cRe[slot] = lane.cRe, g.cIm[slot] = lane.cIm;
      g.firstSample[slot] = lane.firstSample;
      for (std::size_t l = 0; l < channels; ++l) {
        g.gain[l][slot] = lane.gain[l];
        g.gainStep[l][slot] = lane.gainStep[l];
      }
    }
    accumulateOscillatorGroupReference(g, static_cast<int>(channels), masked, accumulator,
                                       static_cast<int>(used));
  }
}

/// The pairwise sum of `width` lane values: the first half plus the second, again and again.
float pairwiseSum(const float* lanes, int width) {
  if (width == 1) return lanes[0];
  float half[kOscillatorLanes];
  for (int i = 0; i < width / 2; ++i) half[i] = lanes[i] + lanes[i + width / 2];
  return pairwiseSum(half, width / 2);
}

}  // namespace

std::vector<std::vector<float>> synthesizeReference(const BubbleTrackSet& tracks,
                                                    const SynthesisSettings& settings) {
  SynthesisReport report;
  const VoiceSet set = prepareVoices(tracks, settings, report);
  const std::size_t channels = tracks.channelCount();
  const RenderContext ctx{settings, OscillatorKernel::baseline, channels, 1.0 / settings.sampleRate,
                          set.frames};
  std::vector<std::vector<float>> out(channels, std::vector<float>(set.frames, 0.0f));
  std::vector<VoiceState> state(set.voices.size());  // each voice at the start of the block
  std::vector<float> accumulator(channels * kBlockSamples * kOscillatorLanes);
  for (std::int64_t b = 0; b * kBlockSamples < set.frames; ++b) {
    std::vector<OscillatorLane> ringing, born;  // through the whole block; from inside it
    for (std::size_t v = 0; v < set.voices.size(); ++v) {
      const Voice& voice = set.voices[v];
      if (b < voice.firstBlock || b >= voice.endBlock) continue;
      if (b == voice.firstBlock) state[v] = startVoice(voice, ctx);
      const VoiceState next = advanceVoice(voice, state[v], (b + 1) * kBlockSamples, ctx);
      (state[v].sample > b * kBlockSamples ? born : ringing)
          .push_back(oscillatorLane(voice, state[v], next, ctx));
      state[v] = next;
    }
    std::fill(accumulator.begin(), accumulator.end(), 0.0f);
    accumulateLanes(ringing, false, channels, accumulator.data());
    accumulateLanes(born, true, channels, accumulator.data());
    for (std::size_t l = 0; l < channels; ++l)
      for (std::int64_t n = 0; n < kBlockSamples && b * kBlockSamples + n < set.frames; ++n)
        out[l][b * kBlockSamples + n] =
            pairwiseSum(&accumulator[(l * kBlockSamples + n) * kOscillatorLanes], kOscillatorLanes);
  }
  addResonatorRings(tracks, settings, out);  // the same rings, added the same way
  return out;
}

}  // namespace fluidsound::acoustics
