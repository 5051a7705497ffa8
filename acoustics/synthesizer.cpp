// acoustics/synthesizer.cpp — synthesis stage (see synthesizer.h, docs/synthesis.md).
//
// Work is split into fixed time segments of kSegmentBlocks blocks, rendered in parallel; each
// segment writes only its own output samples. A bubble that is already ringing when a segment
// starts is brought to the segment start by the same block-by-block phase and amplitude steps it
// would have taken had it been rendered from its birth there, so the result is bit-identical for
// any thread count and any scheduling.
#include "acoustics/synthesizer.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include <tbb/parallel_for.h>

#include "acoustics/bubble_oscillator.h"
#include "acoustics/depth_shift.h"
#include "acoustics/minnaert.h"
#include "acoustics/oscillator_bank.h"
#include "acoustics/track_interpolation.h"

namespace fluidsound::acoustics {

double decayTime(double decayRate, double decibels) {
  return decibels / 20.0 * std::numbers::ln10 / decayRate;
}

namespace {

/// Blocks per parallel work item (16 × 256 samples = 85 ms at 48 kHz): long enough that bringing
/// a ringing bubble up to the segment start costs little, short enough to balance two cores.
constexpr std::int64_t kSegmentBlocks = 16;
/// Segments per progress report.
constexpr std::int64_t kSegmentsPerWave = 32;

/// A bubble prepared for rendering: its constants and the samples it occupies.
struct Voice {
  const BubbleTrack* bubble = nullptr;
  OscillatorConstants oscillator;     ///< deep, at the surface's ambient pressure
  double adiabaticAngularFrequency = 0.0;  ///< ω₀ of the adiabatic model at p₀ [rad/s] (hydrostatic factor)
  std::int64_t firstSample = 0;       ///< first sample at or after birth
  std::int64_t firstBlock = 0;
  std::int64_t endBlock = 0;          ///< one past the block in which it has decayed by the cut-off
};

/// Where a voice stands at a given sample.
struct VoiceState {
  std::int64_t sample = 0;
  double phase = 0.0;            ///< φ [rad], in [0, 2π)
  double magnitude = 0.0;        ///< A e^{−β(t−t_b)} [Pa]
  double angularFrequency = 0.0; ///< instantaneous ω [rad/s]
  std::vector<double> gain;      ///< transfer per listener [-]
};

/// Everything a segment needs about the whole render.
struct RenderContext {
  const SynthesisSettings& settings;
  std::size_t channels;
  double dt;                     ///< sample period [s]
  std::int64_t frames;
};

/// Instantaneous angular frequency [rad/s] of a voice with track values v at time t.
double instantaneousAngularFrequency(const Voice& voice, const TrackValues& v, double t,
                                     const SynthesisSettings& s) {
  const double radius = voice.bubble->radius;
  double w = voice.oscillator.angularFrequency;
  if (std::isfinite(v.depth)) {
    w *= freeSurfaceFrequencyRatio(radius, v.depth);  // Strasberg 1953, docs/physics.md §5
    if (s.model.hydrostatic) {
      // p₀ → p₀ + ρgh acts on the restoring term; applied as the adiabatic model's ratio.
      OscillatorModel adiabatic = s.model;
      adiabatic.polytropic = PolytropicModel::Adiabatic;
      const double p = ambientPressureAt(v.depth, s.liquid, s.model);
      w *= naturalAngularFrequency(radius, p, s.liquid, adiabatic) / voice.adiabaticAngularFrequency;
    }
  }
  if (s.model.chirp)  // van den Doel 2005: f(t) = f₀(1 + ξβt), docs/physics.md §7.4
    w *= 1.0 + s.model.chirpRiseFactor * voice.oscillator.decayRate * (t - voice.bubble->birth);
  // The free response of v̈ + 2βv̇ + ω₀²v = 0 rings at ω_d = √(ω₀² − β²) (docs/physics.md §1).
  const double beta = voice.oscillator.decayRate;
  return std::sqrt(std::max(w * w - beta * beta, 0.0));
}

Voice prepareVoice(const BubbleTrack& bubble, const SynthesisSettings& s) {
  Voice v;
  v.bubble = &bubble;
  const double p0 = s.liquid.ambientPressure;
  v.oscillator = bubbleOscillator(bubble.radius, p0, s.liquid, s.model, bubble.amplitude);
  OscillatorModel adiabatic = s.model;
  adiabatic.polytropic = PolytropicModel::Adiabatic;
  v.adiabaticAngularFrequency = naturalAngularFrequency(bubble.radius, p0, s.liquid, adiabatic);
  v.firstSample = static_cast<std::int64_t>(std::ceil(bubble.birth * s.sampleRate));
  v.firstBlock = v.firstSample / kBlockSamples;
  const double end = bubble.birth + decayTime(v.oscillator.decayRate, s.cutoffDecibels);
  const auto endSample = static_cast<std::int64_t>(std::ceil(end * s.sampleRate));
  v.endBlock = std::max(endSample / kBlockSamples + 1, v.firstBlock + 1);
  return v;
}

/// Highest instantaneous angular frequency a voice reaches [rad/s]. The interpolant is monotone
/// between track samples, so the extremes are at the samples.
double peakAngularFrequency(const Voice& voice, const SynthesisSettings& s) {
  TrackValues v;
  v.depth = std::numeric_limits<double>::infinity();
  double w = instantaneousAngularFrequency(voice, v, voice.bubble->birth, s);
  for (const TrackSample& k : voice.bubble->track) {
    v.depth = k.depth;
    w = std::max(w, instantaneousAngularFrequency(voice, v, voice.bubble->birth, s));
  }
  if (s.model.chirp) w *= 1.0 + s.model.chirpRiseFactor * std::log(std::pow(10.0, s.cutoffDecibels / 20.0));
  return w;
}

/// Starts a voice at its first sample.
VoiceState startVoice(const Voice& voice, TrackInterpolator& interp, TrackValues& values,
                      const RenderContext& ctx) {
  VoiceState st;
  st.sample = voice.firstSample;
  const double t = static_cast<double>(st.sample) * ctx.dt;
  const double age = t - voice.bubble->birth;  // < one sample: birth is not quantised
  interp.evaluate(t, values);
  st.angularFrequency = instantaneousAngularFrequency(voice, values, t, ctx.settings);
  st.phase = std::fmod(st.angularFrequency * age, 2.0 * std::numbers::pi);
  st.magnitude = voice.oscillator.amplitude * std::exp(-voice.oscillator.decayRate * age);
  st.gain = values.transfer;
  return st;
}

/// Advances a voice from st.sample to `sample` (the next block boundary), with ω varying
/// linearly per sample: φ += Δt(Nω_a + Δω N(N−1)/2), Δω = (ω_b − ω_a)/N — exactly what the
/// oscillator recurrence does (docs/synthesis.md).
void advanceVoice(const Voice& voice, VoiceState& st, std::int64_t sample, TrackInterpolator& interp,
                  TrackValues& values, const RenderContext& ctx) {
  const auto n = static_cast<double>(sample - st.sample);
  const double t = static_cast<double>(sample) * ctx.dt;
  interp.evaluate(t, values);
  const double w = instantaneousAngularFrequency(voice, values, t, ctx.settings);
  const double dw = (w - st.angularFrequency) / n;
  st.phase = std::fmod(st.phase + ctx.dt * (n * st.angularFrequency + dw * n * (n - 1.0) / 2.0),
                       2.0 * std::numbers::pi);
  st.magnitude *= std::exp(-voice.oscillator.decayRate * n * ctx.dt);
  st.angularFrequency = w;
  st.gain = values.transfer;
  st.sample = sample;
}

/// Fills lane `lane` of `group` for the stretch from st to the end of the block (whose values
/// at the end are `next`), starting at offset `first` inside the block.
void loadLane(OscillatorGroup& group, int lane, const Voice& voice, const VoiceState& st,
              const VoiceState& next, const RenderContext& ctx) {
  const auto n = static_cast<double>(next.sample - st.sample);
  const std::complex<double> z = std::polar(st.magnitude, st.phase);
  const std::complex<double> r =
      std::polar(std::exp(-voice.oscillator.decayRate * ctx.dt), st.angularFrequency * ctx.dt);
  const double dw = (next.angularFrequency - st.angularFrequency) / n;
  const std::complex<double> c = std::polar(1.0, dw * ctx.dt);
  group.zRe[lane] = static_cast<float>(z.real());
  group.zIm[lane] = static_cast<float>(z.imag());
  group.rRe[lane] = static_cast<float>(r.real());
  group.rIm[lane] = static_cast<float>(r.imag());
  group.cRe[lane] = static_cast<float>(c.real());
  group.cIm[lane] = static_cast<float>(c.imag());
  for (std::size_t l = 0; l < ctx.channels; ++l) {
    group.gain[l][lane] = static_cast<float>(st.gain[l]);
    group.gainStep[l][lane] = static_cast<float>((next.gain[l] - st.gain[l]) / n);
  }
  group.firstSample[lane] = static_cast<float>(st.sample % kBlockSamples);
}

void clearGroup(OscillatorGroup& g) { g = OscillatorGroup{}; }

/// A voice inside one segment: its interpolator, current state and scratch values.
struct SegmentVoice {
  const Voice* voice;
  TrackInterpolator interp;
  TrackValues values;
  VoiceState state;
  bool started = false;
};

void renderSegment(std::int64_t segment, std::span<const Voice> voices,
                   std::span<const std::int64_t> order, std::int64_t maxLifetimeBlocks,
                   const RenderContext& ctx, std::vector<std::vector<float>>& out) {
  const std::int64_t totalBlocks = (ctx.frames + kBlockSamples - 1) / kBlockSamples;
  const std::int64_t b0 = segment * kSegmentBlocks;
  const std::int64_t b1 = std::min(b0 + kSegmentBlocks, totalBlocks);

  // Voices ringing in [b0, b1): sorted by first block, so a window of the order suffices.
  const auto byFirstBlock = [&](std::int64_t i, std::int64_t block) {
    return voices[i].firstBlock < block;
  };
  const auto lo = std::lower_bound(order.begin(), order.end(), b0 - maxLifetimeBlocks, byFirstBlock);
  const auto hi = std::lower_bound(order.begin(), order.end(), b1, byFirstBlock);
  std::vector<SegmentVoice> active;
  for (auto it = lo; it != hi; ++it) {
    const Voice& v = voices[*it];
    if (v.endBlock > b0) active.push_back({&v, TrackInterpolator(*v.bubble, ctx.channels), {}, {}, false});
  }

  std::vector<float> acc(ctx.channels * kBlockSamples * kOscillatorLanes);
  OscillatorGroup full{}, masked{};
  int fullLanes = 0, maskedLanes = 0;
  VoiceState next;
  const int listeners = static_cast<int>(ctx.channels);
  const auto flush = [&](OscillatorGroup& g, int& lanes, bool isMasked) {
    if (lanes == 0) return;
    accumulateOscillatorGroup(g, listeners, isMasked, acc.data());
    clearGroup(g);
    lanes = 0;
  };

  for (std::int64_t b = b0; b < b1; ++b) {
    const std::int64_t blockStart = b * kBlockSamples, blockEnd = blockStart + kBlockSamples;
    std::fill(acc.begin(), acc.end(), 0.0f);
    for (SegmentVoice& sv : active) {
      const Voice& v = *sv.voice;
      if (b < v.firstBlock || b >= v.endBlock) continue;
      if (!sv.started) {
        sv.state = startVoice(v, sv.interp, sv.values, ctx);
        // Catch up from birth to this block, by the same steps a continuous render takes.
        while (sv.state.sample < blockStart) {
          const std::int64_t boundary = (sv.state.sample / kBlockSamples + 1) * kBlockSamples;
          advanceVoice(v, sv.state, boundary, sv.interp, sv.values, ctx);
        }
        sv.started = true;
      }
      next = sv.state;
      advanceVoice(v, next, blockEnd, sv.interp, sv.values, ctx);
      if (sv.state.sample > blockStart) {
        loadLane(masked, maskedLanes++, v, sv.state, next, ctx);
        if (maskedLanes == kOscillatorLanes) flush(masked, maskedLanes, true);
      } else {
        loadLane(full, fullLanes++, v, sv.state, next, ctx);
        if (fullLanes == kOscillatorLanes) flush(full, fullLanes, false);
      }
      std::swap(sv.state, next);
    }
    flush(full, fullLanes, false);
    flush(masked, maskedLanes, true);

    // Sum the lanes in a fixed order into the output.
    const std::int64_t count = std::min(blockEnd, ctx.frames) - blockStart;
    for (std::size_t l = 0; l < ctx.channels; ++l) {
      const float* a = acc.data() + l * kBlockSamples * kOscillatorLanes;
      float* o = out[l].data() + blockStart;
      for (std::int64_t n = 0; n < count; ++n) {
        float sum = 0.0f;
        for (int lane = 0; lane < kOscillatorLanes; ++lane) sum += a[n * kOscillatorLanes + lane];
        o[n] = sum;
      }
    }
  }
}

}  // namespace

SynthesisResult synthesize(const BubbleTrackSet& tracks, const SynthesisSettings& settings,
                           const ProgressCallback& progress) {
  SynthesisResult result;
  SynthesisReport& report = result.report;
  const std::size_t channels = tracks.channelCount();
  const double fs = settings.sampleRate;
  const double nyquistAngular = std::numbers::pi * fs;

  // Prepare every bubble (independent, so in parallel; each writes its own slot).
  std::vector<Voice> prepared(tracks.bubbles.size());
  tbb::parallel_for(std::size_t{0}, tracks.bubbles.size(),
                    [&](std::size_t i) { prepared[i] = prepareVoice(tracks.bubbles[i], settings); });

  double lastEnd = 0.0;
  std::vector<Voice> voices;
  voices.reserve(prepared.size());
  for (const Voice& v : prepared) {
    for (const TrackSample& k : v.bubble->track)
      if (k.depth < kMinimumDepthOverRadius * v.bubble->radius) ++report.depthsClamped;
    if (peakAngularFrequency(v, settings) >= nyquistAngular) {
      ++report.bubblesAboveNyquist;
      continue;
    }
    lastEnd = std::max(lastEnd, v.bubble->birth + decayTime(v.oscillator.decayRate, settings.cutoffDecibels));
    voices.push_back(v);
  }
  const double duration = settings.duration.value_or(lastEnd);
  const auto frames = static_cast<std::int64_t>(std::ceil(duration * fs));
  report.frames = frames;
  std::erase_if(voices, [&](const Voice& v) {
    const bool silent = v.firstSample >= frames;
    report.bubblesSilent += silent;
    return silent;
  });
  report.bubblesRendered = static_cast<std::int64_t>(voices.size());

  // Order by first block (stable: ties keep file order) for the segment windows.
  std::vector<std::int64_t> order(voices.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::int64_t>(i);
  std::stable_sort(order.begin(), order.end(), [&](std::int64_t a, std::int64_t b) {
    return voices[a].firstBlock < voices[b].firstBlock;
  });
  std::int64_t maxLifetimeBlocks = 0;
  const std::int64_t totalBlocks = (frames + kBlockSamples - 1) / kBlockSamples;
  for (const Voice& v : voices) {
    maxLifetimeBlocks = std::max(maxLifetimeBlocks, v.endBlock - v.firstBlock);
    const std::int64_t end = std::min(v.endBlock * kBlockSamples, frames);
    report.oscillatorSamples += std::max<std::int64_t>(0, end - v.firstSample);
  }

  result.channels.assign(channels, std::vector<float>(static_cast<std::size_t>(frames)));
  const RenderContext ctx{settings, channels, 1.0 / fs, frames};
  const std::int64_t segments = (totalBlocks + kSegmentBlocks - 1) / kSegmentBlocks;
  for (std::int64_t w0 = 0; w0 < segments; w0 += kSegmentsPerWave) {
    const std::int64_t w1 = std::min(w0 + kSegmentsPerWave, segments);
    tbb::parallel_for(w0, w1, [&](std::int64_t s) {
      renderSegment(s, voices, order, maxLifetimeBlocks, ctx, result.channels);
    });
    if (progress) progress(static_cast<double>(w1) / static_cast<double>(segments));
  }

  for (const auto& ch : result.channels)
    for (float x : ch) report.peakPascals = std::max(report.peakPascals, static_cast<double>(std::fabs(x)));
  return result;
}

}  // namespace fluidsound::acoustics
