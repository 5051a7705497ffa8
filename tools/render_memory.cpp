// tools/render_memory.cpp — see render_memory.h.
#include "tools/render_memory.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <numbers>

#include "acoustics/bubble/instantaneous_frequency.h"
#include "io/input_error.h"
#include "io/json_validation.h"
#include "io/memory_text.h"
#include "io/render_limits.h"

namespace fluidsound::tools {
namespace {

/// The most samples this machine may render: the fixed limit, or less where memory is smaller.
double sampleLimit(std::uint64_t availableBytes) {
  return availableBytes == 0 ? io::kMaxRenderSamples
                             : std::min(io::kMaxRenderSamples, static_cast<double>(availableBytes) /
                                                                   io::kRenderBytesPerSample);
}

std::string expectedText(std::uint64_t availableBytes) {
  char text[200];
  std::snprintf(text, sizeof text,
                "a render of at most %.4g samples (duration × sample rate × channels: at most "
                "2^31, and %g B each "
                "within this machine's %s of memory)",
                sampleLimit(availableBytes), io::kRenderBytesPerSample,
                availableBytes == 0 ? "unknown amount"
                                    : io::gibibytes(static_cast<double>(availableBytes)).c_str());
  return text;
}

std::string foundText(double seconds, double sampleRate, std::size_t channels) {
  char text[160];
  std::snprintf(
      text, sizeof text, "%.6g s × %.6g Hz × %zu %s = %.4g samples (%s)", seconds, sampleRate,
      channels, channels == 1 ? "channel" : "channels",
      io::renderSamples(seconds, sampleRate, channels),
      io::gibibytes(io::renderSamples(seconds, sampleRate, channels) * io::kRenderBytesPerSample)
          .c_str());
  return text;
}

/// The default length of a render without a duration, as the synthesizer computes it: the latest
/// end of ring-down (birth + 90 dB decay) over the bubbles below Nyquist; `last` is set to the
/// index of that bubble (unchanged when none).
double defaultDuration(const acoustics::BubbleTrackSet& tracks,
                       const acoustics::SynthesisSettings& s, std::size_t& last) {
  double end = 0.0;
  const double nyquistAngular = std::numbers::pi * s.sampleRate;
  for (std::size_t i = 0; i < tracks.bubbles.size(); ++i) {
    const acoustics::BubbleTrack& bubble = tracks.bubbles[i];
    const acoustics::RingingBubble ringing = acoustics::ringingBubble(bubble, s.liquid, s.model);
    if (acoustics::peakAngularFrequency(ringing, bubble, s.cutoffDecibels, s.liquid, s.model) >=
        nyquistAngular)
      continue;
    const double bubbleEnd =
        bubble.birth + acoustics::decayTime(ringing.deep.decayRate, s.cutoffDecibels);
    if (!(bubbleEnd <= end)) end = bubbleEnd, last = i;  // NaN or infinite ends are caught too
  }
  return end;
}

}  // namespace

void requireMemoryForRender(const acoustics::BubbleTrackSet& tracks, const std::string& inputFile,
                            const acoustics::SynthesisSettings& settings,
                            const std::optional<double>& durationOption,
                            std::uint64_t availableBytes) {
  const std::size_t channels = acoustics::outputChannelListeners(tracks).size();
  std::size_t last = 0;
  const double seconds =
      settings.duration ? *settings.duration : defaultDuration(tracks, settings, last);
  if (io::renderSamples(seconds, settings.sampleRate, channels) <= sampleLimit(availableBytes))
    return;
  const std::string expected = expectedText(availableBytes),
                    found = foundText(seconds, settings.sampleRate, channels);
  if (durationOption)
    throw CLI::ValidationError("--duration: expected " + expected + ", found " + found);
  if (tracks.duration) throw io::InputError(inputFile, "duration", expected, found);
  throw io::InputError(
      inputFile, io::elementPath("bubbles", last),
      expected + "; without duration the render lasts until the last bubble has rung down", found);
}

void requireMemoryForRender(const sim::Scene& scene, const std::string& sceneFile,
                            std::uint64_t availableBytes) {
  std::size_t channels = 0;  // two per head
  for (const sim::Listener& l : scene.listeners) channels += l.head ? 2 : 1;
  if (io::renderSamples(scene.time.duration, scene.sampleRate, channels) <=
      sampleLimit(availableBytes))
    return;
  throw io::InputError(sceneFile, "time.duration", expectedText(availableBytes),
                       foundText(scene.time.duration, scene.sampleRate, channels) +
                           " (audio.sample_rate, one channel per listener, two per head)");
}

}  // namespace fluidsound::tools
