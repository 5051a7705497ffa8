// acoustics/analysis/centroid_prediction.cpp — predicted band energy and centroid per listener (see
// centroid_prediction.h). Serial and in bubble order: the sums are the same bits on every run.
#include "acoustics/analysis/centroid_prediction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "acoustics/analysis/damped_sine_spectrum.h"
#include "acoustics/bubble/instantaneous_frequency.h"
#include "acoustics/synthesis/track_interpolation.h"

namespace fluidsound::acoustics {
namespace {

/// Midpoints of the energy integral per bubble. Each carries 1/32 of the bubble's energy; the rule
/// is exact for constant transfer and frequency, and the track changes little within one
/// point's span (≤ the decay time 1/2β ≤ 10 ms for R ≤ 5 mm, against a 33 ms frame).
constexpr int kEnergyPoints = 32;

}  // namespace

std::vector<PredictedSpectrum> predictedSpectra(const BubbleTrackSet& tracks,
                                                const SynthesisSettings& settings,
                                                const FrequencyBand& band) {
  const std::size_t channels = tracks.channelCount();
  const double clipEnd = settings.duration.value_or(std::numeric_limits<double>::infinity());
  const double nyquistAngular = std::numbers::pi * settings.sampleRate;
  std::vector<PredictedSpectrum> result(channels);
  std::vector<double> moment(channels, 0.0);
  const DampedSineSpectrum lineSpectrum(settings.sampleRate);
  for (const BubbleTrack& bubble : tracks.bubbles) {
    const RingingBubble ringing = ringingBubble(bubble, settings.liquid, settings.model);
    // The synthesizer's Nyquist guard and its silent bubbles (first sample at or after the end).
    if (peakAngularFrequency(ringing, bubble, settings.cutoffDecibels, settings.liquid,
                             settings.model) >= nyquistAngular)
      continue;
    const double beta = ringing.deep.decayRate;
    const double lifetime =
        std::min(decayTime(beta, settings.cutoffDecibels), clipEnd - bubble.birth);
    if (!(std::ceil(bubble.birth * settings.sampleRate) <
          std::ceil(clipEnd * settings.sampleRate)) ||
        !(lifetime > 0.0))
      continue;
    for (PredictedSpectrum& p : result) ++p.bubbles;
    // Each point carries 1/N of the share U = 1 − e^{−2βT} of the decay's energy that falls
    // before the cut (the weight e^{−2βτ}dτ = du/2β is uniform in u ∈ [0, U]).
    const double reach = -std::expm1(-2.0 * beta * lifetime);                         // U
    const double amplitudeSquared = ringing.deep.amplitude * ringing.deep.amplitude;  // [Pa²]
    const TrackInterpolator track(bubble, channels);
    std::size_t cursor = 0;
    for (int j = 0; j < kEnergyPoints; ++j) {  // u increasing: times increase, as the cursor needs
      const double u = reach * (j + 0.5) / kEnergyPoints;
      const double t = bubble.birth - std::log1p(-u) / (2.0 * beta);
      const TrackValues values = track.evaluate(t, cursor);
      const double w =
          instantaneousAngularFrequency(ringing, values.depth, t, settings.liquid, settings.model);
      if (!(w > 0.0)) continue;  // overdamped (ω_d = 0): rendered silent
      const BandSpectrum line = lineSpectrum.inBand(w, beta, band);
      for (std::size_t l = 0; l < channels; ++l) {
        const double energy = amplitudeSquared * values.transfer[l] * values.transfer[l] *
                              line.energy * reach / kEnergyPoints;
        result[l].bandEnergy += energy;
        moment[l] += energy * line.centroid;
      }
    }
  }
  for (std::size_t l = 0; l < channels; ++l)
    result[l].centroid = result[l].bandEnergy > 0.0 ? moment[l] / result[l].bandEnergy : 0.0;
  return result;
}

}  // namespace fluidsound::acoustics
