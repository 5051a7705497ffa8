// tools/synth_command.cpp — `fluidsound synth` (see synth_command.h, docs/cli.md).
#include "tools/synth_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "acoustics/oscillator_bank.h"
#include "acoustics/synthesizer.h"
#include "io/audio_file.h"
#include "io/bubble_track_file.h"
#include "io/input_error.h"
#include "io/spectrogram_image.h"
#include "io/text_file.h"
#include "tools/progress_display.h"
#include "tools/render_memory.h"
#include "tools/run_report.h"
#include "tools/solver_memory.h"

namespace fluidsound::tools {

CLI::App* addSynthCommand(CLI::App& app, SynthOptions& o) {
  CLI::App* c = app.add_subcommand("synth", "render bubble tracks (fluidsound.bubbles/1) to audio");
  c->add_option("bubbles", o.input, "bubble-track file (JSON)")->required();
  c->add_option("-o,--output", o.output, "output audio file, .wav or .flac")->required();
  addAudioOutputOptions(*c, o.audio);
  c->add_option("--duration", o.duration, "length of the render in seconds")
      ->check(CLI::PositiveNumber);
  c->add_option("--report", o.report, "run report (default: OUT with extension .report.json)");
  c->add_option("--spectrogram", o.spectrogram, "also draw the spectrogram to this PNG");
  addOscillatorModelOptions(*c, o.model);
  addCommonOptions(*c, o.common);
  return c;
}

namespace {

std::filesystem::path defaultReportPath(const std::filesystem::path& output) {
  std::filesystem::path p = output;
  return p.replace_extension(".report.json");
}

void note(const SynthOptions& o, const std::string& text) {
  if (!o.common.quiet) std::fprintf(stderr, "fluidsound: note: %s\n", text.c_str());
}

}  // namespace

int runSynthCommand(const SynthOptions& o) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const std::filesystem::path output = o.output;
  const std::filesystem::path reportPath = o.report.empty() ? defaultReportPath(output) : std::filesystem::path(o.report);
  // Fail before the render, not after it, when an output cannot be written.
  io::requireWritableFolder(output);
  io::requireWritableFolder(reportPath);
  if (!o.spectrogram.empty()) io::requireWritableFolder(o.spectrogram);

  std::error_code sizeError;
  const auto inputBytes = std::filesystem::file_size(o.input, sizeError);
  constexpr std::uintmax_t kAnnounceReadBytes = 8u << 20;  // a read that takes about a second
  if (!sizeError && inputBytes > kAnnounceReadBytes)
    note(o, "reading " + o.input + " (" + std::to_string(inputBytes >> 20) + " MB)");
  const acoustics::BubbleTrackSet tracks = io::readBubbleTracks(o.input);
  if (tracks.channelCount() > static_cast<std::size_t>(acoustics::kMaxListeners))
    throw io::InputError(o.input, "listeners", "at most " + std::to_string(acoustics::kMaxListeners) +
                         " listeners", std::to_string(tracks.listeners.size()));
  const auto t1 = Clock::now();

  acoustics::SynthesisSettings settings;
  settings.sampleRate = o.audio.sampleRate.value_or(tracks.sampleRate);
  settings.duration = o.duration ? o.duration : tracks.duration;
  settings.model = o.model;
  requireMemoryForRender(tracks, o.input, settings, o.duration, physicalMemoryBytes());
  acoustics::SynthesisResult result;
  {
    const double audioSeconds = settings.duration.value_or(0.0);
    ProgressDisplay progress("synth", audioSeconds > 0 ? audioSeconds : 1.0,
                             audioSeconds > 0 ? "s audio" : "", o.common.quiet);
    result = acoustics::synthesize(tracks, settings, [&](double f) { progress.update(f); });
  }
  const auto t2 = Clock::now();
  const acoustics::SynthesisReport& r = result.report;
  if (r.bubblesAboveNyquist > 0)
    note(o, std::to_string(r.bubblesAboveNyquist) + " bubble(s) dropped: frequency at or above Nyquist (" +
                std::to_string(settings.sampleRate / 2) + " Hz)");
  if (r.depthsClamped > 0)
    note(o, std::to_string(r.depthsClamped) + " track sample(s) shallower than 1.25 R: depth shift clamped");

  io::AudioBuffer audio{settings.sampleRate, std::move(result.channels)};
  const io::AudioWriteSettings write = audioWriteSettings(o.audio, output, tracks.listeners);
  const io::AudioWriteReport w = io::writeAudio(output, audio, write);
  warnAboutAudioOutput(w, o.common.quiet);
  if (!o.spectrogram.empty()) io::writeSpectrogramPng(o.spectrogram, audio, {}, output.filename().string());
  const auto t3 = Clock::now();

  RunReport report("synth");
  report.setting("input", o.input);
  report.setting("output", o.output);
  report.setting("sample_rate", settings.sampleRate);
  report.setOscillatorModel(settings.model);
  report.stageSeconds("read", std::chrono::duration<double>(t1 - t0).count());
  report.stageSeconds("synthesis", std::chrono::duration<double>(t2 - t1).count());
  report.stageSeconds("write", std::chrono::duration<double>(t3 - t2).count());
  report.result("bubbles_in_file", static_cast<double>(tracks.bubbles.size()));
  report.result("bubbles_rendered", static_cast<double>(r.bubblesRendered));
  report.result("bubbles_above_nyquist", static_cast<double>(r.bubblesAboveNyquist));
  report.result("bubbles_after_end", static_cast<double>(r.bubblesSilent));
  report.result("depths_clamped", static_cast<double>(r.depthsClamped));
  report.result("oscillator_samples", static_cast<double>(r.oscillatorSamples));
  report.result("duration_seconds", static_cast<double>(r.frames) / settings.sampleRate);
  report.result("channels", static_cast<double>(audio.channels.size()));
  report.result("peak_pascals", r.peakPascals);
  report.result("gain", w.gain);
  report.result("output_peak_dbfs", w.outputPeakDbfs);
  report.result("clipped_samples", static_cast<double>(w.clippedSamples));
  reportAudioOutput(report, write, w);
  const double synthSeconds = std::chrono::duration<double>(t2 - t1).count();
  report.result("oscillator_samples_per_second",
                synthSeconds > 0 ? static_cast<double>(r.oscillatorSamples) / synthSeconds : 0.0);
  report.write(reportPath);

  if (!o.common.quiet)
    std::fprintf(stderr, "fluidsound: wrote %s (%zu ch, %.2f s, peak %.3g Pa) in %.2f s\n",
                 output.string().c_str(), audio.channels.size(),
                 static_cast<double>(r.frames) / settings.sampleRate, r.peakPascals,
                 std::chrono::duration<double>(t3 - t0).count());
  return kExitSuccess;
}

}  // namespace fluidsound::tools
