// tools/synth_command.cpp — `fluidsound synth` (see synth_command.h, docs/cli.md).
#include "tools/synth_command.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <optional>

#include "acoustics/synthesis/synthesis_stage.h"
#include "io/audio_file.h"
#include "io/interruption.h"
#include "io/output_file.h"
#include "tools/number_checks.h"
#include "tools/render_memory.h"
#include "tools/run_report.h"
#include "tools/solver_memory.h"
#include "tools/stage_progress.h"
#include "tools/synth_files.h"
#include "tools/synth_report.h"

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

void note(const SynthOptions& o, const std::string& text) {
  if (!o.common.quiet) std::fprintf(stderr, "fluidsound: note: %s\n", text.c_str());
}

/// acoustics::synthesize with the terminal's progress line; a signal stops it (io::Interrupted).
acoustics::SynthesisStageResult renderWithProgress(const acoustics::BubbleTrackSet& tracks,
                                                   const SynthOptions& o) {
  acoustics::SynthesisOptions options{o.audio.sampleRate, o.duration, o.model, std::nullopt};
  const acoustics::SynthesisSettings settings = acoustics::synthesisSettings(tracks, options);
  requireMemoryForRender(tracks, o.input, settings, o.duration, physicalMemoryBytes());
  std::optional<acoustics::HrirTable> heads;
  if (!tracks.heads.empty()) options.headResponses = &heads.emplace(readHeadResponses(tracks, o.input, settings.sampleRate));
  StageProgress observer("synth", "s audio", o.common.quiet);
  try {
    acoustics::SynthesisStageResult result = acoustics::synthesize(tracks, options, observer);
    observer.finish();
    return result;
  } catch (const StageInterrupted& e) {
    throw io::Interrupted(io::interruptionSignal(), e.what());
  }
}

}  // namespace

nlohmann::ordered_json renderSynth(const SynthOptions& o, const acoustics::BubbleTrackSet* tracks) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const std::string reportPath = checkedSynthOutputs(o);  // fail before the render, not after it
  std::optional<acoustics::BubbleTrackSet> read;
  if (!tracks) tracks = &read.emplace(readSynthInput(o));
  const auto t1 = Clock::now();
  acoustics::SynthesisStageResult result = renderWithProgress(*tracks, o);
  const auto t2 = Clock::now();
  const acoustics::SynthesisReport& r = result.report;
  if (r.bubblesAboveNyquist > 0)
    note(o, std::to_string(r.bubblesAboveNyquist) +
                " bubble(s) dropped: frequency at or above Nyquist (" +
                std::to_string(result.settings.sampleRate / 2) + " Hz)");
  if (r.depthsClamped > 0)
    note(o, std::to_string(r.depthsClamped) + " track sample(s) shallower than 1.25 R: depth shift clamped");

  const std::size_t channels = result.channels.size();
  const io::AudioBuffer audio{result.settings.sampleRate, std::move(result.channels)};
  const io::AudioWriteSettings write = audioWriteSettings(o.audio, o.output, acoustics::outputChannelNames(*tracks));
  io::OutputBatch outputs;
  const io::AudioWriteReport w = addSynthFiles(outputs, o, audio, write);
  RunReport report("synth");
  addSynthResults(report, o, {result, channels, tracks->bubbles.size(), write, w});
  report.stageSeconds("read", std::chrono::duration<double>(t1 - t0).count());
  report.stageSeconds("synthesis", result.seconds);
  report.stageSeconds("write", std::chrono::duration<double>(Clock::now() - t2).count());
  report.result("oscillator_samples_per_second", result.oscillatorSamplesPerSecond());
  nlohmann::ordered_json document = report.document();
  if (!reportPath.empty()) outputs.add(reportPath, jsonFileText(document));
  io::throwIfInterrupted("synth, before writing");
  outputs.commit();

  warnAboutAudioOutput(w, o.common.quiet);
  if (!o.common.quiet)
    std::fprintf(stderr, "fluidsound: wrote %s (%zu ch, %.2f s, peak %.3g Pa) in %.2f s\n",
                 io::isStandardOutput(o.output) ? "standard output" : o.output.c_str(), channels,
                 result.durationSeconds(), r.peakPascals,
                 std::chrono::duration<double>(Clock::now() - t0).count());
  return document;
}

int runSynthCommand(const SynthOptions& o) {
  renderSynth(o);
  return kExitSuccess;
}

}  // namespace fluidsound::tools
