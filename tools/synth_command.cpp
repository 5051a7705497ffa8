// tools/synth_command.cpp — `fluidsound synth` (see synth_command.h, docs/cli.md).
#include "tools/synth_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "acoustics/synthesis/oscillator_bank.h"
#include "acoustics/synthesis/synthesizer.h"
#include "io/audio_file.h"
#include "io/bubble_track_file.h"
#include "io/input_error.h"
#include "io/interruption.h"
#include "io/output_file.h"
#include "io/spectrogram_image.h"
#include "io/text_file.h"
#include "tools/number_checks.h"
#include "tools/progress_display.h"
#include "tools/render_memory.h"
#include "tools/run_report.h"
#include "tools/solver_memory.h"

namespace fluidsound::tools {

CLI::App* addSynthCommand(CLI::App& app, SynthOptions& o) {
  CLI::App* c = app.add_subcommand("synth", "render bubble tracks (fluidsound.bubbles/1) to audio");
  c->add_option("bubbles", o.input, "bubble-track file (JSON)")->required();
  c->add_option("-o,--output", o.output, "output audio file, .wav or .flac; - = standard output")
      ->required();
  addAudioOutputOptions(*c, o.audio);
  c->add_option("--duration", o.duration, "length of the render in seconds")
      ->check(finitePositive());
  c->add_option("--report", o.report, "run report (default: OUT.report.json; none for -, a device or a FIFO)");
  c->add_option("--spectrogram", o.spectrogram, "also draw the spectrogram to this PNG");
  addOscillatorModelOptions(*c, o.model);
  addCommonOptions(*c, o.common);
  return c;
}

namespace {

/// OUT.report.json beside a file output (so out.wav and out.flac keep their own reports); none for
/// a stream (`-`, a device, a FIFO): a report there would land in /dev or mix with the audio.
std::string defaultReportPath(const std::string& output) {
  if (io::resolveOutput(output).kind != io::OutputKind::Replace) return {};
  return output + ".report.json";
}

/// The shown name of an output: "standard output" for `-`.
std::string shownName(const std::string& path) {
  return io::isStandardOutput(path) ? std::string("standard output") : path;
}

void note(const SynthOptions& o, const std::string& text) {
  if (!o.common.quiet) std::fprintf(stderr, "fluidsound: note: %s\n", text.c_str());
}

/// Refuses, before the render, every output that cannot be written or names an input or another
/// output (the audio format is checked by audioLayout()).
/// @return the report's path; empty: no report (a stream output without --report)
std::string checkedReportPath(const SynthOptions& o) {
  const std::string reportPath = o.report.empty() ? defaultReportPath(o.output) : o.report;
  requireDistinctFiles({{"bubbles", o.input, true},
                        {"--output", o.output},
                        {"--report", reportPath},
                        {"--spectrogram", o.spectrogram}});
  io::requireWritableFolder(o.output);
  if (!reportPath.empty()) io::requireWritableFolder(reportPath);
  if (!o.spectrogram.empty()) io::requireWritableFolder(o.spectrogram);
  return reportPath;
}

/// The settings and results of a render (docs/cli.md lists the fields); stage times are added by
/// the caller.
void addSynthResults(RunReport& report, const SynthOptions& o, const acoustics::SynthesisSettings& settings,
                      const io::AudioWriteSettings& write, const acoustics::BubbleTrackSet& tracks,
                      const acoustics::SynthesisReport& r, const io::AudioWriteReport& w,
                     std::size_t channels) {
  report.setting("input", o.input);
  report.setting("output", o.output);
  report.setting("sample_rate", settings.sampleRate);
  report.setOscillatorModel(settings.model);
  report.result("bubbles_in_file", static_cast<double>(tracks.bubbles.size()));
  report.result("bubbles_rendered", static_cast<double>(r.bubblesRendered));
  report.result("bubbles_above_nyquist", static_cast<double>(r.bubblesAboveNyquist));
  report.result("bubbles_after_end", static_cast<double>(r.bubblesSilent));
  report.result("depths_clamped", static_cast<double>(r.depthsClamped));
  report.result("oscillator_samples", static_cast<double>(r.oscillatorSamples));
  report.result("duration_seconds", static_cast<double>(r.frames) / settings.sampleRate);
  report.result("channels", static_cast<double>(channels));
  report.result("peak_pascals", r.peakPascals);
  // The inner loop that ran (acoustics/synthesis/oscillator_kernel.h): a speed figure says what it measured.
  report.result("oscillator_kernel", std::string(acoustics::oscillatorKernelName(r.kernel)));
  report.result("gain", w.gain);
  report.result("output_peak_dbfs", w.outputPeakDbfs);
  report.result("clipped_samples", static_cast<double>(w.clippedSamples));
  reportAudioOutput(report, write, w);  // format, bits, normalisation, scale, loudness, channels
}

}  // namespace

int runSynthCommand(const SynthOptions& o) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  // Fail before the render, not after it, when an output cannot be written.
  audioLayout(o.output, o.audio.format, o.audio.bits);  // the name, --format and --bits agree
  const std::string reportPath = checkedReportPath(o);

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
    result = acoustics::synthesize(tracks, settings, [&](double f) {
      io::throwIfInterrupted("synth, " + std::to_string(std::lround(f * 100)) + " % rendered");
      progress.update(f);
    });
  }
  const auto t2 = Clock::now();
  const acoustics::SynthesisReport& r = result.report;
  if (r.bubblesAboveNyquist > 0)
    note(o, std::to_string(r.bubblesAboveNyquist) + " bubble(s) dropped: frequency at or above Nyquist (" +
                std::to_string(settings.sampleRate / 2) + " Hz)");
  if (r.depthsClamped > 0)
    note(o, std::to_string(r.depthsClamped) + " track sample(s) shallower than 1.25 R: depth shift clamped");

  io::AudioBuffer audio{settings.sampleRate, std::move(result.channels)};
  const io::AudioWriteSettings write = audioWriteSettings(o.audio, o.output, tracks.listeners);
  // All outputs are encoded first, then written together: a failure leaves none of them.
  io::EncodedAudio encoded = io::encodeAudio(o.output, audio, write);
  const io::AudioWriteReport w = encoded.report;
  io::OutputBatch outputs;
  outputs.add(o.output, std::move(encoded.bytes));
  if (!o.spectrogram.empty()) {
    const std::string title = io::isStandardOutput(o.output) ? std::string("standard output")
                                                             : std::filesystem::path(o.output).filename().string();
    outputs.add(o.spectrogram, io::encodeSpectrogramPng(audio, {}, title));
  }
  const auto t3 = Clock::now();
  if (!reportPath.empty()) {
    RunReport report("synth");
    addSynthResults(report, o, settings, write, tracks, r, w, audio.channels.size());
    const double synthSeconds = std::chrono::duration<double>(t2 - t1).count();
    report.stageSeconds("read", std::chrono::duration<double>(t1 - t0).count());
    report.stageSeconds("synthesis", synthSeconds);
    report.stageSeconds("write", std::chrono::duration<double>(t3 - t2).count());
    report.result("oscillator_samples_per_second",
                  synthSeconds > 0 ? static_cast<double>(r.oscillatorSamples) / synthSeconds : 0.0);
    outputs.add(reportPath, report.text());
  }
  io::throwIfInterrupted("synth, before writing");
  outputs.commit();

  warnAboutAudioOutput(w, o.common.quiet);
  if (!o.common.quiet)
    std::fprintf(stderr, "fluidsound: wrote %s (%zu ch, %.2f s, peak %.3g Pa) in %.2f s\n",
                 shownName(o.output).c_str(), audio.channels.size(),
                 static_cast<double>(r.frames) / settings.sampleRate, r.peakPascals,
                 std::chrono::duration<double>(Clock::now() - t0).count());
  return kExitSuccess;
}

}  // namespace fluidsound::tools
