// acoustics/synthesis/synthesizer.cpp — synthesis stage (see synthesizer.h, docs/synthesis.md).
//
// Work is split into fixed time segments of kSegmentBlocks blocks, rendered in parallel; each
// segment writes only its own output samples. A bubble that is already ringing when a segment
// starts is brought to the segment start by the same block-by-block phase and amplitude steps it
// would have taken had it been rendered from its birth there, so the result is bit-identical for
// any thread count and any scheduling.
#include "acoustics/synthesis/synthesizer.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>

#include "acoustics/synthesis/oscillator_bank.h"
#include "acoustics/synthesis/resonator_rings.h"
#include "acoustics/synthesis/synthesis_voice.h"

namespace fluidsound::acoustics {

double decayTime(double decayRate, double decibels) {
  return decibels / 20.0 * std::numbers::ln10 / decayRate;
}

namespace {

/// Blocks per parallel work item (32 × 512 samples = 0.34 s at 48 kHz): long enough that bringing
/// a ringing bubble up to the segment start costs little, short enough to balance two cores.
constexpr std::int64_t kSegmentBlocks = 32;
/// Segments per progress report.
constexpr std::int64_t kSegmentsPerWave = 8;

/// The packed record of one voice over one block: its OscillatorLane as flat floats — z, r, c
/// (complex, re/im), the first sample, then per listener the gain and its step. Voices are
/// scheduled into these first (voice by voice, so each voice's track stays in cache) and rendered
/// block by block afterwards. synthesizer_reference.cpp renders the same lanes unpacked.
constexpr std::size_t kLaneHeader = 7;

void appendLane(std::vector<float>& lanes, const Voice& voice, const VoiceState& st,
                const VoiceState& next, const RenderContext& ctx) {
  const OscillatorLane lane = oscillatorLane(voice, st, next, ctx);
  lanes.insert(lanes.end(),
               {lane.zRe, lane.zIm, lane.rRe, lane.rIm, lane.cRe, lane.cIm, lane.firstSample});
  for (std::size_t l = 0; l < ctx.channels; ++l) {
    lanes.push_back(lane.gain[l]);
    lanes.push_back(lane.gainStep[l]);
  }
}

/// Renders flat lanes (appendLane) in groups of kOscillatorLanes into the accumulator.
/// @return the most lanes one group used
int accumulateLanes(const std::vector<float>& lanes, bool masked, const RenderContext& ctx,
                    float* accumulator) {
  int widest = 0;
  const std::size_t stride = kLaneHeader + 2 * ctx.channels, count = lanes.size() / stride;
  for (std::size_t first = 0; first < count; first += kOscillatorLanes) {
    OscillatorGroup g{};
    for (std::size_t lane = 0; lane < kOscillatorLanes && first + lane < count; ++lane) {
      const float* p = lanes.data() + (first + lane) * stride;
      g.zRe[lane] = p[0];
      g.zIm[lane] = p[1];
      g.rRe[lane] = p[2];
      g.rIm[lane] = p[3];
      g.cRe[lane] = p[4];
      g.cIm[lane] = p[5];
      g.firstSample[lane] = p[6];
      for (std::size_t l = 0; l < ctx.channels; ++l) {
        g.gain[l][lane] = p[kLaneHeader + 2 * l];
        g.gainStep[l][lane] = p[kLaneHeader + 2 * l + 1];
      }
    }
    const int used = static_cast<int>(std::min<std::size_t>(kOscillatorLanes, count - first));
    accumulateOscillatorGroup(ctx.kernel, g, static_cast<int>(ctx.channels), masked, accumulator,
                              used);
    widest = std::max(widest, used);
  }
  return widest;
}

/// The lanes to render in one block: voices that ring through it, and voices born inside it.
struct BlockSchedule {
  std::vector<float> full, masked;
};

/// Scratch memory of one worker thread, reused from segment to segment. Its contents are
/// rebuilt for every segment, so which thread renders a segment never shows in the output.
struct SegmentScratch {
  std::vector<BlockSchedule> schedule;
  std::vector<float> accumulator;
};

/// Schedules blocks [b0, b1), voice by voice: each voice's state at every block boundary.
void scheduleSegment(std::int64_t b0, std::int64_t b1, std::span<const Voice> voices,
                     std::int64_t maxLifetimeBlocks, const RenderContext& ctx,
                     std::vector<BlockSchedule>& schedule) {
  // Voices ringing in [b0, b1): sorted by first block, so a window of the order suffices.
  const auto byFirstBlock = [](const Voice& v, std::int64_t block) { return v.firstBlock < block; };
  const auto lo =
      std::lower_bound(voices.begin(), voices.end(), b0 - maxLifetimeBlocks, byFirstBlock);
  const auto hi = std::lower_bound(voices.begin(), voices.end(), b1, byFirstBlock);
  schedule.resize(static_cast<std::size_t>(b1 - b0));
  for (BlockSchedule& block : schedule) {
    block.full.clear();
    block.masked.clear();
  }
  for (auto it = lo; it != hi; ++it) {
    const Voice& v = *it;
    if (v.endBlock <= b0) continue;
    VoiceState state = startVoice(v, ctx);
    // A voice born before the segment is brought to its start by the same block steps a
    // continuous render takes, so segment boundaries leave no trace in the output.
    while (state.sample < b0 * kBlockSamples)
      state = advanceVoice(v, state, (state.sample / kBlockSamples + 1) * kBlockSamples, ctx);
    for (std::int64_t b = std::max(b0, v.firstBlock); b < std::min(b1, v.endBlock); ++b) {
      const VoiceState next = advanceVoice(v, state, (b + 1) * kBlockSamples, ctx);
      BlockSchedule& block = schedule[static_cast<std::size_t>(b - b0)];
      appendLane(state.sample > b * kBlockSamples ? block.masked : block.full, v, state, next, ctx);
      state = next;
    }
  }
}

void renderSegment(std::int64_t segment, std::span<const Voice> voices,
                   std::int64_t maxLifetimeBlocks, const RenderContext& ctx,
                   SegmentScratch& scratch, std::vector<std::vector<float>>& out) {
  const std::int64_t totalBlocks = (ctx.frames + kBlockSamples - 1) / kBlockSamples;
  const std::int64_t b0 = segment * kSegmentBlocks;
  const std::int64_t b1 = std::min(b0 + kSegmentBlocks, totalBlocks);
  scheduleSegment(b0, b1, voices, maxLifetimeBlocks, ctx, scratch.schedule);
  // Render, block by block.
  std::vector<float>& acc = scratch.accumulator;
  acc.resize(ctx.channels * kBlockSamples * kOscillatorLanes);
  for (std::int64_t b = b0; b < b1; ++b) {
    const std::int64_t blockStart = b * kBlockSamples;
    const BlockSchedule& block = scratch.schedule[static_cast<std::size_t>(b - b0)];
    if (block.full.empty() && block.masked.empty()) continue;  // silent: the output is already 0
    std::fill(acc.begin(), acc.end(), 0.0f);
    const int lanes = std::max(accumulateLanes(block.full, false, ctx, acc.data()),
                               accumulateLanes(block.masked, true, ctx, acc.data()));
    // Sum the lanes in a fixed order into the output.
    float* channels[kMaxListeners];
    for (std::size_t l = 0; l < ctx.channels; ++l) channels[l] = out[l].data() + blockStart;
    sumOscillatorLanes(
        acc.data(), static_cast<int>(ctx.channels),
        static_cast<int>(std::min(blockStart + kBlockSamples, ctx.frames) - blockStart), channels,
        lanes);
  }
}

}  // namespace

SynthesisResult synthesize(const BubbleTrackSet& tracks, const SynthesisSettings& settings,
                           const ProgressCallback& progress) {
  SynthesisResult result;
  SynthesisReport& report = result.report;
  report.kernel = settings.kernel.value_or(fastestOscillatorKernel());
  if (!cpuRunsOscillatorKernel(report.kernel))
    throw std::invalid_argument("synthesize: this CPU cannot run the oscillator kernel " +
                                std::string(oscillatorKernelName(report.kernel)));
  const std::size_t channels = tracks.channelCount();
  const VoiceSet set = prepareVoices(tracks, settings, report);
  const std::int64_t frames = set.frames;
  result.channels.assign(channels, std::vector<float>(static_cast<std::size_t>(frames)));
  const RenderContext ctx{settings, report.kernel, channels, 1.0 / settings.sampleRate, frames};
  const std::int64_t totalBlocks = (frames + kBlockSamples - 1) / kBlockSamples;
  const std::int64_t segments = (totalBlocks + kSegmentBlocks - 1) / kSegmentBlocks;
  tbb::enumerable_thread_specific<SegmentScratch> scratch;
  for (std::int64_t w0 = 0; w0 < segments; w0 += kSegmentsPerWave) {
    const std::int64_t w1 = std::min(w0 + kSegmentsPerWave, segments);
    tbb::parallel_for(w0, w1, [&](std::int64_t s) {
      renderSegment(s, set.voices, set.maxLifetimeBlocks, ctx, scratch.local(), result.channels);
    });
    if (progress) progress(static_cast<double>(w1) / static_cast<double>(segments));
  }
  report.ringSamples = addResonatorRings(tracks, settings, result.channels);
  for (const auto& ch : result.channels)
    for (float x : ch)
      report.peakPascals = std::max(report.peakPascals, static_cast<double>(std::fabs(x)));
  return result;
}

}  // namespace fluidsound::acoustics
