// tools/run_summary.cpp — see run_summary.h.
#include "tools/run_summary.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "acoustics/analysis/centroid_prediction.h"
#include "acoustics/analysis/power_spectrum.h"
#include "acoustics/analysis/spectrum_statistics.h"
#include "io/audio_file.h"

namespace fluidsound::tools {

using Json = nlohmann::ordered_json;

namespace {

/// Welch segment of the measured spectrum: 16384 samples (2.93 Hz bins at 48 kHz); the centroid
/// does not depend on it (Parseval: any segment length holds the record's energy; 4096 … 32768
/// move the pour's centroid by < 0.01 %).
constexpr std::size_t kSpectrumSegmentSamples = 16384;
/// Band of the centroid [Hz]: the audible range, or up to Nyquist if that is lower.
constexpr double kCentroidLowHz = 20.0, kCentroidHighHz = 20000.0;

/// The centroid of one channel in `band`; null without energy there.
Json measuredCentroid(const io::AudioBuffer& audio, std::size_t channel,
                      const acoustics::FrequencyBand& band) {
  if (audio.frameCount() == 0) return nullptr;
  const acoustics::PowerSpectrum spectrum = acoustics::welchPowerSpectrum(
      audio.channels[channel], audio.sampleRate, kSpectrumSegmentSamples);
  double power = 0.0;
  for (std::size_t k = 0; k < spectrum.power.size(); ++k)
    if (spectrum.frequency(k) >= band.low && spectrum.frequency(k) <= band.high)
      power += spectrum.power[k];
  if (power > 0.0) return acoustics::spectralCentroid(spectrum, band);
  return nullptr;
}

}  // namespace

Json radiusHistogram(const acoustics::BubbleTrackSet& tracks) {
  constexpr int kBins = 10;
  constexpr double kLow = 1e-4, kDecades = 2.0;
  std::vector<int> counts(kBins, 0);
  for (const acoustics::BubbleTrack& b : tracks.bubbles) {
    const int bin = static_cast<int>(std::floor(std::log10(b.radius / kLow) / kDecades * kBins));
    ++counts[std::clamp(bin, 0, kBins - 1)];
  }
  Json bins = Json::array();
  for (int i = 0; i < kBins; ++i)
    bins.push_back({{"radius_from_m", kLow * std::pow(10.0, kDecades * i / kBins)},
                    {"radius_to_m", kLow * std::pow(10.0, kDecades * (i + 1) / kBins)},
                    {"bubbles", counts[i]}});
  return bins;
}

void addSynthSummary(Json& run, const Json& synthReport) {
  if (!synthReport.is_object() || !synthReport.contains("results")) return;
  const Json& r = synthReport["results"];
  if (r.contains("peak_pascals")) run["peak_pascals"] = r["peak_pascals"];
  if (r.contains("output_peak_dbfs")) run["peak_dbfs"] = r["output_peak_dbfs"];
  if (r.contains("oscillator_kernel")) run["oscillator_kernel"] = r["oscillator_kernel"];
  if (r.contains("audio_output"))
    run["audio_output"] = r["audio_output"];  // scale, gain, loudness, names
}

Json spectrumSummary(const acoustics::BubbleTrackSet& tracks,
                     const std::filesystem::path& audioPath,
                     const std::optional<double>& sampleRate) {
  const io::AudioBuffer audio = io::readAudio(audioPath);
  // What the synth stage renders with: its rate, the file's duration.
  acoustics::SynthesisSettings settings;
  settings.sampleRate = sampleRate.value_or(tracks.sampleRate);
  settings.duration = tracks.duration;
  const acoustics::FrequencyBand band{kCentroidLowHz,
                                      std::min(kCentroidHighHz, audio.sampleRate / 2.0)};
  const std::vector<acoustics::PredictedSpectrum> predicted =
      acoustics::predictedSpectra(tracks, settings, band);
  // A head's two ears are predicted as its centre: the prediction knows no head.
  const std::vector<std::size_t> listenerOf = acoustics::outputChannelListeners(tracks);
  const std::vector<std::string> names = acoustics::outputChannelNames(tracks);
  Json channels = Json::array();
  for (std::size_t c = 0; c < audio.channels.size(); ++c) {
    const std::size_t l = c < listenerOf.size() ? listenerOf[c] : predicted.size();
    const bool heard = l < predicted.size() && predicted[l].bandEnergy > 0.0;
    Json channel = {{"channel", c}};
    if (c < names.size()) channel["listener"] = names[c];
    channel["centroid_measured_hz"] = measuredCentroid(audio, c, band);
    channel["centroid_predicted_hz"] = heard ? Json(predicted[l].centroid) : Json(nullptr);
    channels.push_back(channel);
  }
  return {{"band_hz", {band.low, band.high}}, {"channels", channels}};
}

}  // namespace fluidsound::tools
