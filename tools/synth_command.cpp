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

namespace {

/// Adds the extra stems into the bubbles' channels (the mix), padding nothing: each stem has the
/// render's length.
void mixInto(std::vector<std::vector<float>>& channels, const ExtraStems& extra) {
  for (const auto& stem : extra.stems)
    for (std::size_t c = 0; c < channels.size() && c < stem.size(); ++c)
      for (std::size_t i = 0; i < channels[c].size() && i < stem[c].size(); ++i) channels[c][i] += stem[c][i];
}

/// Encodes each stem, scaled by the audio's gain, as a 32-bit float WAV in the stem folder.
nlohmann::ordered_json addStemFiles(io::OutputBatch& outputs, const MixedSources& mixed, double sampleRate,
                                    const std::vector<std::vector<float>>& bubbles, const ExtraStems& extra,
                                    double gain, const std::vector<std::string>& channelNames) {
  nlohmann::ordered_json files = nlohmann::ordered_json::object();
  const auto add = [&](const std::string& name, const std::vector<std::vector<float>>& stem) {
    io::AudioBuffer buffer{sampleRate, stem};
    for (auto& channel : buffer.channels)
      for (float& x : channel) x = static_cast<float>(x * gain);
    io::AudioWriteSettings write;
    write.channelNames = channelNames;
    const std::filesystem::path path = mixed.stemFolder / (name + ".wav");
    outputs.add(path, io::encodeAudio(path, buffer, write).bytes);
    files[name] = path.string();
  };
  add("bubbles", bubbles);
  for (std::size_t k = 0; k < extra.names.size(); ++k) add(extra.names[k], extra.stems[k]);
  return files;
}

}  // namespace

nlohmann::ordered_json renderSynth(const SynthOptions& o, const acoustics::BubbleTrackSet* tracks,
                                   const MixedSources* mixed) {
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
  std::optional<ExtraStems> extra;
  std::vector<std::vector<float>> bubbles;
  if (mixed) {
    extra = mixed->render(static_cast<std::size_t>(r.frames), result.settings.sampleRate);
    bubbles = result.channels;
    mixInto(result.channels, *extra);
  }
  const io::AudioBuffer audio{result.settings.sampleRate, std::move(result.channels)};
  const io::AudioWriteSettings write = audioWriteSettings(o.audio, o.output, acoustics::outputChannelNames(*tracks));
  io::OutputBatch outputs;
  const io::AudioWriteReport w = addSynthFiles(outputs, o, audio, write);
  RunReport report("synth");
  addSynthResults(report, o, {result, channels, tracks->bubbles.size(), write, w});
  if (extra) {
    report.resultJson("stems", addStemFiles(outputs, *mixed, audio.sampleRate, bubbles, *extra, w.gain, write.channelNames).dump());
    report.resultJson("solids", extra->report.dump());
  }
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
