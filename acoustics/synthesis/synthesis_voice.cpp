// acoustics/synthesis/synthesis_voice.cpp — see synthesis_voice.h.
#include "acoustics/synthesis/synthesis_voice.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <span>
#include <utility>

#include "acoustics/bubble/depth_shift.h"

namespace fluidsound::acoustics {

namespace {

/// Below this per-sample phase change the rotation e^{iθ} is taken from its Taylor series
/// (error θ⁶/720 < 1e-21), saving a sincos per bubble and block.
constexpr double kSmallAngle = 1e-3;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Instantaneous damped angular frequency [rad/s] of a voice with track values v at time t.
double voiceAngularFrequency(const Voice& voice, const TrackValues& v, double t,
                             const SynthesisSettings& s) {
  return instantaneousAngularFrequency(voice.ringing, v.depth, t, s.liquid, s.model);
}

Voice prepareVoice(const BubbleTrack& bubble, std::size_t channels, std::span<double> trackStorage,
                   const SynthesisSettings& s) {
  const double dt = 1.0 / s.sampleRate;
  Voice v{ringingBubble(bubble, s.liquid, s.model),
          TrackInterpolator(bubble, channels, trackStorage)};
  v.sampleDecay = std::exp(-v.ringing.deep.decayRate * dt);
  v.blockDecay = std::exp(-v.ringing.deep.decayRate * kBlockSamples * dt);
  v.firstSample = static_cast<std::int64_t>(std::ceil(bubble.birth * s.sampleRate));
  v.firstBlock = v.firstSample / kBlockSamples;
  v.endTime = bubble.birth + decayTime(v.ringing.deep.decayRate, s.cutoffDecibels);
  v.endSample =
      std::max(static_cast<std::int64_t>(std::ceil(v.endTime * s.sampleRate)), v.firstSample + 1);
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

/// The bubbles' indices by first sample (ties in file order), so that each segment reads a
/// contiguous run of voices.
std::vector<std::pair<std::int64_t, std::size_t>> renderOrder(const BubbleTrackSet& tracks,
                                                              double fs) {
  const std::size_t count = tracks.bubbles.size();
  std::vector<std::pair<std::int64_t, std::size_t>> order(count);
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
    order[i] = {static_cast<std::int64_t>(std::ceil(tracks.bubbles[i].birth * fs)), i};
  });
  tbb::parallel_sort(order.begin(), order.end());  // keys are unique: the order is deterministic
  return order;
}

/// Drops the aliased voices and those born after the end (stable, so the order holds).
void dropUnheard(std::vector<Voice>& voices, const std::vector<char>& aliased,
                 SynthesisReport& report) {
  std::size_t kept = 0;
  for (std::size_t k = 0; k < voices.size(); ++k) {
    if (aliased[k]) continue;
    if (voices[k].firstSample >= report.frames) {
      ++report.bubblesSilent;
      continue;
    }
    if (kept != k) voices[kept] = std::move(voices[k]);
    ++kept;
  }
  voices.resize(kept);
  report.bubblesRendered = static_cast<std::int64_t>(kept);
}

}  // namespace

VoiceSet prepareVoices(const BubbleTrackSet& tracks, const SynthesisSettings& settings,
                       SynthesisReport& report) {
  const std::size_t channels = tracks.channelCount();
  const double fs = settings.sampleRate;
  const double nyquistAngular = std::numbers::pi * fs;
  // Every bubble prepared in its slot of the render order, in parallel.
  VoiceSet set;
  VoiceSet::Preparation& work = set.preparation;
  work.order = renderOrder(tracks, fs);
  const std::vector<std::pair<std::int64_t, std::size_t>>& order = work.order;
  const std::size_t count = order.size();
  // All track tables in one array, in render order.
  std::vector<std::size_t>& trackOffset = work.trackOffset;
  trackOffset.assign(count + 1, 0);
  for (std::size_t k = 0; k < count; ++k)
    trackOffset[k + 1] =
        trackOffset[k] + TrackInterpolator::storageSize(tracks.bubbles[order[k].second], channels);
  // Left uninitialised (every entry is written by its voice, in parallel): tens of MB for 10⁵
  // bubbles.
  set.trackStorage.reset(new double[trackOffset[count]]);
  set.voices.resize(count);
  std::vector<char>& aliased = work.aliased;
  std::vector<std::int64_t>& clamped = work.clamped;
  aliased.assign(count, 0);
  clamped.assign(count, 0);
  double* const storage = set.trackStorage.get();
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t k) {
    const BubbleTrack& bubble = tracks.bubbles[order[k].second];
    set.voices[k] =
        prepareVoice(bubble, channels,
                     std::span(storage + trackOffset[k], storage + trackOffset[k + 1]), settings);
    aliased[k] = peakAngularFrequency(set.voices[k].ringing, bubble, settings.cutoffDecibels,
                                      settings.liquid, settings.model) >= nyquistAngular;
    clamped[k] = std::count_if(bubble.track.begin(), bubble.track.end(), [&](const TrackSample& s) {
      return s.depth < kMinimumDepthOverRadius * bubble.radius;
    });
  });
  // Counts and the default duration.
  double lastEnd = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    report.depthsClamped += clamped[k];
    report.bubblesAboveNyquist += aliased[k];
    if (!aliased[k]) lastEnd = std::max(lastEnd, set.voices[k].endTime);
  }
  const double duration = settings.duration.value_or(lastEnd);
  set.frames = report.frames = static_cast<std::int64_t>(std::ceil(duration * fs));
  dropUnheard(set.voices, aliased, report);
  for (const Voice& v : set.voices) {
    set.maxLifetimeBlocks = std::max(set.maxLifetimeBlocks, v.endBlock - v.firstBlock);
    // Counted to the cut-off time: the rest of the last block is computed but not credited.
    report.oscillatorSamples += std::min(v.endSample, set.frames) - v.firstSample;
  }
  return set;
}

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
  next.magnitude = st.magnitude * (count == kBlockSamples
                                       ? voice.blockDecay
                                       : std::exp(-voice.ringing.deep.decayRate * n * ctx.dt));
  return next;
}

OscillatorLane oscillatorLane(const Voice& voice, const VoiceState& st, const VoiceState& next,
                              const RenderContext& ctx) {
  const auto n = static_cast<double>(next.sample - st.sample);
  const std::complex<double> z = std::polar(st.magnitude, st.phase);
  const std::complex<double> r = voice.sampleDecay * std::polar(1.0, st.angularFrequency * ctx.dt);
  const std::complex<double> c =
      unitRotation((next.angularFrequency - st.angularFrequency) / n * ctx.dt);
  OscillatorLane lane{static_cast<float>(z.real()),
                      static_cast<float>(z.imag()),
                      static_cast<float>(r.real()),
                      static_cast<float>(r.imag()),
                      static_cast<float>(c.real()),
                      static_cast<float>(c.imag()),
                      static_cast<float>(st.sample % kBlockSamples),
                      {},
                      {}};
  for (std::size_t l = 0; l < ctx.channels; ++l) {
    lane.gain[l] = static_cast<float>(st.values.transfer[l]);
    lane.gainStep[l] = static_cast<float>((next.values.transfer[l] - st.values.transfer[l]) / n);
  }
  return lane;
}

}  // namespace fluidsound::acoustics
