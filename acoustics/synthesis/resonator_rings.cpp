// acoustics/synthesis/resonator_rings.cpp — see resonator_rings.h.
#include "acoustics/synthesis/resonator_rings.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "acoustics/bubble/instantaneous_frequency.h"

namespace fluidsound::acoustics {

namespace {

/// Adds one ring of a bubble of amplitude A [Pa at 1 m] born at `birth` [s] to the channels.
std::int64_t addRing(const ResonatorRing& ring, double amplitude, double birth, const SynthesisSettings& settings,
                     std::vector<std::vector<float>>& channels) {
  const double fs = settings.sampleRate;
  if (!(ring.frequency < fs / 2.0) || !(ring.decayRate > 0.0)) return 0;
  const std::complex<double> pole(-ring.decayRate, 2.0 * std::numbers::pi * ring.frequency);
  const auto first = static_cast<std::int64_t>(std::ceil(birth * fs));
  const auto length = static_cast<std::int64_t>(std::ceil(decayTime(ring.decayRate, settings.cutoffDecibels) * fs));
  const std::complex<double> step = std::exp(pole / fs);
  std::int64_t added = 0;
  for (std::size_t l = 0; l < channels.size() && l < ring.gain.size(); ++l) {
    std::vector<float>& out = channels[l];
    const auto end = std::min<std::int64_t>(first + length, static_cast<std::int64_t>(out.size()));
    if (first >= end || ring.gain[l] == 0.0) continue;
    std::complex<double> z = std::exp(pole * (static_cast<double>(first) / fs - birth)) *
                             std::polar(amplitude * ring.gain[l], ring.phase[l]);
    for (std::int64_t n = first; n < end; ++n, z *= step) out[static_cast<std::size_t>(n)] += static_cast<float>(z.real());
    added += end - first;
  }
  return added;
}

}  // namespace

std::int64_t addResonatorRings(const BubbleTrackSet& tracks, const SynthesisSettings& settings,
                               std::vector<std::vector<float>>& channels) {
  std::int64_t added = 0;
  for (const BubbleTrack& bubble : tracks.bubbles) {
    if (bubble.rings.empty()) continue;
    const double amplitude = ringingBubble(bubble, settings.liquid, settings.model).deep.amplitude;
    for (const ResonatorRing& ring : bubble.rings) added += addRing(ring, amplitude, bubble.birth, settings, channels);
  }
  return added;
}

}  // namespace fluidsound::acoustics
