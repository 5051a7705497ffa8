// acoustics/synthesis/synthesizer.cpp — synthesis stage (see synthesizer.h, docs/synthesis.md).
//
// Work is split into fixed time segments of kSegmentBlocks blocks, rendered in parallel; each
// segment writes only its own output samples. A bubble that is already ringing when a segment
// starts is brought to the segment start by the same block-by-block phase and amplitude steps it
// would have taken had it been rendered from its birth there, so the result is bit-identical for
// any thread count and any scheduling.
#include "acoustics/synthesis/synthesizer.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "acoustics/bubble/depth_shift.h"
#include "acoustics/bubble/instantaneous_frequency.h"
#include "acoustics/synthesis/oscillator_bank.h"
#include "acoustics/synthesis/track_interpolation.h"

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
/// Below this per-sample phase change the rotation e^{iθ} is taken from its Taylor series
/// (error θ⁶/720 < 1e-21), saving a sincos per bubble and block.
constexpr double kSmallAngle = 1e-3;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// A bubble prepared for rendering: its constants, its track and the samples it occupies.
struct Voice {
  const BubbleTrack* bubble = nullptr;     ///< only while preparing; rendering reads the copies below
  RingingBubble ringing;                   ///< R, t_b, deep constants (instantaneous_frequency.h)
  TrackInterpolator track;
  double sampleDecay = 0.0;                ///< e^{−βΔt}
  double blockDecay = 0.0;                 ///< e^{−βBΔt}, B = kBlockSamples
  std::int64_t firstSample = 0;            ///< first sample at or after birth
  std::int64_t firstBlock = 0;
  double endTime = 0.0;                    ///< time it has decayed by the cut-off [s]
  std::int64_t endSample = 0;              ///< first sample after endTime
  std::int64_t endBlock = 0;               ///< one past the block that holds endSample − 1
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

/// Everything a segment needs about the whole render.
struct RenderContext {
  const SynthesisSettings& settings;
  OscillatorKernel kernel;
  std::size_t channels;
  double dt;                      ///< sample period [s]
  std::int64_t frames;
};

/// Instantaneous damped angular frequency [rad/s] of a voice with track values v at time t.
double voiceAngularFrequency(const Voice& voice, const TrackValues& v, double t, const SynthesisSettings& s) {
  return instantaneousAngularFrequency(voice.ringing, v.depth, t, s.liquid, s.model);
}

Voice prepareVoice(const BubbleTrack& bubble, std::size_t channels, std::span<double> trackStorage,
                   const SynthesisSettings& s) {
  const double dt = 1.0 / s.sampleRate;
  Voice v{&bubble, ringingBubble(bubble, s.liquid, s.model), TrackInterpolator(bubble, channels, trackStorage)};
  v.sampleDecay = std::exp(-v.ringing.deep.decayRate * dt);
  v.blockDecay = std::exp(-v.ringing.deep.decayRate * kBlockSamples * dt);
  v.firstSample = static_cast<std::int64_t>(std::ceil(bubble.birth * s.sampleRate));
  v.firstBlock = v.firstSample / kBlockSamples;
  v.endTime = bubble.birth + decayTime(v.ringing.deep.decayRate, s.cutoffDecibels);
  v.endSample = std::max(static_cast<std::int64_t>(std::ceil(v.endTime * s.sampleRate)), v.firstSample + 1);
  v.endBlock = (v.endSample - 1) / kBlockSamples + 1;
  return v;
}

double wrapPhase(double phase) { return phase - kTwoPi * std::floor(phase / kTwoPi); }

/// e^{iθ}, by Taylor series for small θ.
std::complex<double> unitRotation(double theta) {
  if (std::fabs(theta) >= kSmallAngle) return std::polar(1.0, theta);
  const double t2 = theta * theta;
  return {1.0 - t2 / 2.0 + t2 * t2 / 24.0, theta * (1.0 - t2 / 6.0 + t2 * t2 / 120.0)};
}

/// Starts a voice at its first sample.
VoiceState startVoice(const Voice& voice, const RenderContext& ctx) {
  VoiceState st;
  st.sample = voice.firstSample;
  const double t = static_cast<double>(st.sample) * ctx.dt;
  const double age = t - voice.ringing.birth;  // < one sample: birth is not quantised
  st.values = voice.track.evaluate(t, st.cursor);
  st.angularFrequency = voiceAngularFrequency(voice, st.values, t, ctx.settings);
  st.phase = wrapPhase(st.angularFrequency * age);
  st.magnitude = voice.ringing.deep.amplitude * std::exp(-voice.ringing.deep.decayRate * age);
  return st;
}

/// The state of a voice at `sample` (the next block boundary) from its state `st`, with ω varying
/// linearly per sample: φ += Δt(Nω_a + Δω N(N−1)/2), Δω = (ω_b − ω_a)/N — exactly what the
/// oscillator recurrence does (docs/synthesis.md).
VoiceState advanceVoice(const Voice& voice, const VoiceState& st, std::int64_t sample,
                        const RenderContext& ctx) {
  VoiceState next;
  next.sample = sample;
  next.cursor = st.cursor;
  const std::int64_t count = sample - st.sample;
  const auto n = static_cast<double>(count);
  const double t = static_cast<double>(sample) * ctx.dt;
  next.values = voice.track.evaluate(t, next.cursor);
  next.angularFrequency = voiceAngularFrequency(voice, next.values, t, ctx.settings);
  const double dw = (next.angularFrequency - st.angularFrequency) / n;
  next.phase = wrapPhase(st.phase + ctx.dt * (n * st.angularFrequency + dw * n * (n - 1.0) / 2.0));
  next.magnitude = st.magnitude * (count == kBlockSamples ? voice.blockDecay
                                                          : std::exp(-voice.ringing.deep.decayRate * n * ctx.dt));
  return next;
}

/// Oscillator parameters of one voice over one block, flat: z, r, c (complex, re/im), the first
/// sample, then per listener the gain and its step. Voices are scheduled into these first (voice by
/// voice, so each voice's track stays in cache) and rendered block by block afterwards.
constexpr std::size_t kLaneHeader = 7;

void appendLane(std::vector<float>& lanes, const Voice& voice, const VoiceState& st,
                const VoiceState& next, const RenderContext& ctx) {
  const auto n = static_cast<double>(next.sample - st.sample);
  const std::complex<double> z = std::polar(st.magnitude, st.phase);
  const std::complex<double> r = voice.sampleDecay * std::polar(1.0, st.angularFrequency * ctx.dt);
  const std::complex<double> c = unitRotation((next.angularFrequency - st.angularFrequency) / n * ctx.dt);
  lanes.insert(lanes.end(), {static_cast<float>(z.real()), static_cast<float>(z.imag()),
                             static_cast<float>(r.real()), static_cast<float>(r.imag()),
                             static_cast<float>(c.real()), static_cast<float>(c.imag()),
                             static_cast<float>(st.sample % kBlockSamples)});
  for (std::size_t l = 0; l < ctx.channels; ++l) {
    lanes.push_back(static_cast<float>(st.values.transfer[l]));
    lanes.push_back(static_cast<float>((next.values.transfer[l] - st.values.transfer[l]) / n));
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
    accumulateOscillatorGroup(ctx.kernel, g, static_cast<int>(ctx.channels), masked, accumulator, used);
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

void renderSegment(std::int64_t segment, std::span<const Voice> voices, std::int64_t maxLifetimeBlocks,
                   const RenderContext& ctx, SegmentScratch& scratch,
                   std::vector<std::vector<float>>& out) {
  const std::int64_t totalBlocks = (ctx.frames + kBlockSamples - 1) / kBlockSamples;
  const std::int64_t b0 = segment * kSegmentBlocks;
  const std::int64_t b1 = std::min(b0 + kSegmentBlocks, totalBlocks);

  // Voices ringing in [b0, b1): sorted by first block, so a window of the order suffices.
  const auto byFirstBlock = [](const Voice& v, std::int64_t block) { return v.firstBlock < block; };
  const auto lo = std::lower_bound(voices.begin(), voices.end(), b0 - maxLifetimeBlocks, byFirstBlock);
  const auto hi = std::lower_bound(voices.begin(), voices.end(), b1, byFirstBlock);

  // Schedule, voice by voice: each voice's state at every block boundary of the segment.
  std::vector<BlockSchedule>& schedule = scratch.schedule;
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

  // Render, block by block.
  std::vector<float>& acc = scratch.accumulator;
  acc.resize(ctx.channels * kBlockSamples * kOscillatorLanes);
  for (std::int64_t b = b0; b < b1; ++b) {
    const std::int64_t blockStart = b * kBlockSamples;
    const BlockSchedule& block = schedule[static_cast<std::size_t>(b - b0)];
    if (block.full.empty() && block.masked.empty()) continue;  // silent: the output is already 0
    std::fill(acc.begin(), acc.end(), 0.0f);
    const int lanes = std::max(accumulateLanes(block.full, false, ctx, acc.data()),
                               accumulateLanes(block.masked, true, ctx, acc.data()));
    // Sum the lanes in a fixed order into the output.
    float* channels[kMaxListeners];
    for (std::size_t l = 0; l < ctx.channels; ++l) channels[l] = out[l].data() + blockStart;
    sumOscillatorLanes(acc.data(), static_cast<int>(ctx.channels),
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
  const double fs = settings.sampleRate;
  const double nyquistAngular = std::numbers::pi * fs;

  // Order by first sample (ties in file order), so that each segment reads a contiguous run of
  // voices; then prepare every bubble in its slot, in parallel.
  const std::size_t count = tracks.bubbles.size();
  std::vector<std::pair<std::int64_t, std::size_t>> order(count);
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
    order[i] = {static_cast<std::int64_t>(std::ceil(tracks.bubbles[i].birth * fs)), i};
  });
  tbb::parallel_sort(order.begin(), order.end());  // keys are unique: the order is deterministic
  // All track tables in one array, in render order.
  std::vector<std::size_t> trackOffset(count + 1, 0);
  for (std::size_t k = 0; k < count; ++k)
    trackOffset[k + 1] = trackOffset[k] + TrackInterpolator::storageSize(tracks.bubbles[order[k].second], channels);
  // Left uninitialised (every entry is written by its voice, in parallel): tens of MB for 10⁵ bubbles.
  const std::unique_ptr<double[]> trackStorage(new double[trackOffset[count]]);
  std::vector<Voice> voices(count);
  std::vector<char> aliased(count);
  std::vector<std::int64_t> clamped(count);
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t k) {
    const BubbleTrack& bubble = tracks.bubbles[order[k].second];
    voices[k] = prepareVoice(bubble, channels,
                             std::span(trackStorage.get() + trackOffset[k], trackStorage.get() + trackOffset[k + 1]),
                             settings);
    aliased[k] = peakAngularFrequency(voices[k].ringing, bubble, settings.cutoffDecibels, settings.liquid,
                                      settings.model) >= nyquistAngular;
    clamped[k] = std::count_if(bubble.track.begin(), bubble.track.end(), [&](const TrackSample& s) {
      return s.depth < kMinimumDepthOverRadius * bubble.radius;
    });
  });

  // Counts and the default duration.
  double lastEnd = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    report.depthsClamped += clamped[k];
    report.bubblesAboveNyquist += aliased[k];
    if (!aliased[k]) lastEnd = std::max(lastEnd, voices[k].endTime);
  }
  const double duration = settings.duration.value_or(lastEnd);
  const auto frames = static_cast<std::int64_t>(std::ceil(duration * fs));
  report.frames = frames;

  // Drop the aliased and those born after the end (stable, so the order holds).
  std::size_t kept = 0;
  for (std::size_t k = 0; k < count; ++k) {
    if (aliased[k]) continue;
    if (voices[k].firstSample >= frames) {
      ++report.bubblesSilent;
      continue;
    }
    if (kept != k) voices[kept] = std::move(voices[k]);
    ++kept;
  }
  voices.resize(kept);
  report.bubblesRendered = static_cast<std::int64_t>(kept);
  std::int64_t maxLifetimeBlocks = 0;
  for (const Voice& v : voices) {
    maxLifetimeBlocks = std::max(maxLifetimeBlocks, v.endBlock - v.firstBlock);
    // Counted to the cut-off time: the rest of the last block is computed but not credited.
    report.oscillatorSamples += std::min(v.endSample, frames) - v.firstSample;
  }

  result.channels.assign(channels, std::vector<float>(static_cast<std::size_t>(frames)));
  const RenderContext ctx{settings, report.kernel, channels, 1.0 / fs, frames};
  const std::int64_t totalBlocks = (frames + kBlockSamples - 1) / kBlockSamples;
  const std::int64_t segments = (totalBlocks + kSegmentBlocks - 1) / kSegmentBlocks;
  tbb::enumerable_thread_specific<SegmentScratch> scratch;
  for (std::int64_t w0 = 0; w0 < segments; w0 += kSegmentsPerWave) {
    const std::int64_t w1 = std::min(w0 + kSegmentsPerWave, segments);
    tbb::parallel_for(w0, w1, [&](std::int64_t s) {
      renderSegment(s, voices, maxLifetimeBlocks, ctx, scratch.local(), result.channels);
    });
    if (progress) progress(static_cast<double>(w1) / static_cast<double>(segments));
  }

  for (const auto& ch : result.channels)
    for (float x : ch) report.peakPascals = std::max(report.peakPascals, static_cast<double>(std::fabs(x)));
  return result;
}

}  // namespace fluidsound::acoustics
