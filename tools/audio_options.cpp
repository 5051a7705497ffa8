// tools/audio_options.cpp — the audio output options of `synth` and `run` (see audio_options.h).
#include "tools/audio_options.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "tools/command_options.h"
#include "tools/number_checks.h"
#include "tools/run_report.h"

namespace fluidsound::tools {
namespace {

/// 1 Pa in dB SPL: 20·log10(1 Pa / 20 µPa), the reference pressure in air (ISO 1683).
constexpr double kDecibelsSplOfOnePascal = 93.9794;

/// A level for JSON: null when it is not finite (−∞ for silence).
nlohmann::ordered_json level(double decibels) {
  return std::isfinite(decibels) ? nlohmann::ordered_json(decibels)
                                 : nlohmann::ordered_json(nullptr);
}

/// "1.0 = 1 Pa = 94.0 dB SPL", or with a gain g "1.0 = 1/g Pa = … dB SPL".
std::string scaleText(double gain) {
  char text[96];
  std::snprintf(text, sizeof text, "1.0 = %.6g Pa = %.1f dB SPL", 1.0 / gain,
                kDecibelsSplOfOnePascal - 20.0 * std::log10(gain));
  return text;
}

}  // namespace

void addAudioOutputOptions(CLI::App& c, AudioOutputOptions& o) {
  c.add_option("--rate", o.sampleRate, "sample rate in Hz (default: the bubble file's sample_rate)")
      ->check(finiteRange(8000.0, 768000.0));
  c.add_option("--format", o.format, "wav or flac (default: from the output's extension; WAV for -, a device or a FIFO)")
      ->check(CLI::IsMember({"wav", "flac"}, CLI::ignore_case));
  c.add_option("--bits", o.bits, "bits per sample: 32 (float), 24 or 16 (PCM with TPDF dither)")
      ->check(CLI::IsMember({16, 24, 32}));
  CLI::Option* normalize = c.add_option("--normalize", o.normalizeDbfs,
                                        "scale so the peak is at this level, dBFS (e.g. -1)")
                               ->check(finiteRange(-120.0, 0.0));
  CLI::Option* loudness = c.add_option("--loudness", o.loudnessLufs,
                                       "scale to this integrated loudness, LUFS (EBU R 128: -23), "
                                       "under the --true-peak ceiling")
                              ->check(finiteRange(-70.0, 0.0))
                              ->excludes(normalize);
  c.add_option(
       "--true-peak", o.truePeakDbtp,
       "with --loudness: lower the gain so the true peak stays at or below this, dBTP (default -1)")
      ->check(finiteRange(-70.0, 0.0))
      ->needs(loudness);
}

io::AudioWriteSettings audioWriteSettings(const AudioOutputOptions& o,
                                          const std::filesystem::path& output,
                                          std::vector<std::string> channelNames) {
  const AudioLayout layout = audioLayout(output.string(), o.format, o.bits);
  io::AudioWriteSettings write;
  write.format = layout.format;
  write.bitsPerSample = layout.bits;
  write.normalizePeakDbfs = o.normalizeDbfs;
  if (o.loudnessLufs) write.loudness = io::LoudnessTarget{*o.loudnessLufs, o.truePeakDbtp};
  write.channelNames = std::move(channelNames);
  return write;
}

std::string audioOptionsFingerprint(const AudioOutputOptions& o) {
  char text[200];
  std::snprintf(text, sizeof text,
                "rate %.17g format %s bits %d normalize %.17g loudness %.17g true-peak %.17g",
                o.sampleRate.value_or(0.0), o.format.c_str(), o.bits, o.normalizeDbfs.value_or(1.0),
                o.loudnessLufs.value_or(1.0), o.truePeakDbtp);
  return text;
}

void reportAudioOutput(RunReport& report, const io::AudioWriteSettings& s,
                       const io::AudioWriteReport& w) {
  report.setting("format", s.format == io::AudioFormat::Flac ? "flac" : "wav");
  report.setting("bits", s.bitsPerSample);
  if (s.normalizePeakDbfs) report.setting("normalize_dbfs", *s.normalizePeakDbfs);
  if (s.loudness) {
    report.setting("loudness_target_lufs", s.loudness->integratedLufs);
    report.setting("true_peak_ceiling_dbtp", s.loudness->truePeakCeilingDbtp);
  }
  nlohmann::ordered_json audio;
  audio["scale"] = scaleText(w.gain);
  audio["calibrated"] = w.gain == 1.0;
  audio["gain"] = w.gain;
  audio["gain_db"] = 20.0 * std::log10(w.gain);
  audio["integrated_loudness_lufs"] = w.written.integratedLufs
                                          ? nlohmann::ordered_json(*w.written.integratedLufs)
                                          : nlohmann::ordered_json(nullptr);
  audio["true_peak_dbtp"] = level(w.written.truePeakDbtp);
  audio["sample_peak_dbfs"] = level(w.outputPeakDbfs);
  audio["true_peak_limited"] = w.truePeakLimited;
  if (s.loudness) audio["loudness_unmeasured"] = w.loudnessUnmeasured;
  audio["channels"] = s.channelNames;
  report.resultJson("audio_output", audio.dump());
}

void warnAboutAudioOutput(const io::AudioWriteReport& w, bool quiet) {
  if (w.clippedSamples > 0)
    std::fprintf(stderr,
                 "fluidsound: warning: %lld sample(s) clipped at full scale; use --normalize or "
                 "--loudness\n",
                 static_cast<long long>(w.clippedSamples));
  else if (w.outputPeakDbfs > 0.0 && !quiet)
    std::fprintf(stderr,
                 "fluidsound: warning: peak %.3g Pa is %+.1f dBFS in a float file; players will "
                 "clip it: use "
                 "--normalize or --loudness\n",
                 w.inputPeak, w.outputPeakDbfs);
  if (w.loudnessUnmeasured)
    std::fprintf(stderr,
                 "fluidsound: warning: no integrated loudness (silence, or shorter than 0.4 s): "
                 "not normalised\n");
  if (quiet) return;
  if (w.truePeakLimited && w.written.integratedLufs)
    std::fprintf(stderr,
                 "fluidsound: note: gain lowered to keep the true peak at %.1f dBTP: loudness %.1f "
                 "LUFS, short of "
                 "the target\n",
                 w.written.truePeakDbtp, *w.written.integratedLufs);
}

}  // namespace fluidsound::tools
