// tools/run_command.cpp — see run_command.h.
#include "tools/run_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "acoustics/analysis/centroid_prediction.h"
#include "acoustics/analysis/power_spectrum.h"
#include "acoustics/analysis/spectrum_statistics.h"
#include "io/audio_file.h"
#include "io/bubble_track_file.h"
#include "io/file_digest.h"
#include "io/frame_folder.h"
#include "io/input_error.h"
#include "io/interruption.h"
#include "io/scene_file.h"
#include "io/text_file.h"
#include "tools/cell_option.h"
#include "tools/render_memory.h"
#include "tools/solver_memory.h"
#include "tools/run_report.h"
#include "tools/simulate_command.h"
#include "tools/stage_records.h"
#include "tools/synth_command.h"
#include "tools/transfer_command.h"

namespace fluidsound::tools {

CLI::App* addRunCommand(CLI::App& app, RunOptions& o) {
  CLI::App* c = app.add_subcommand(
      "run", "the whole pipeline: simulate -> transfer -> synth, to NAME.wav, spectrogram.png and report.json");
  c->add_option("scene", o.scene, "scene file (fluidsound.scene/1)")->required();
  c->add_option("-o,--output", o.output, "output folder")->required();
  c->add_flag("--fresh", o.fresh, "run every stage again, even if its artefacts are up to date");
  addCellOption(*c, o.cell);
  addAudioOutputOptions(*c, o.audio);
  addOscillatorModelOptions(*c, o.model);
  addCommonOptions(*c, o.common);
  return c;
}

namespace {
using Json = nlohmann::ordered_json;

std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The inputs' fingerprint: the scene file, the grid cell size it runs at (the file's or
/// --cell's), every mesh it names and the program's version.
std::string inputHash(const sim::Scene& scene) {
  std::uint64_t h = io::fnv1a64(fileBytes(scene.file));
  char cell[40];
  std::snprintf(cell, sizeof cell, "cell %.17g m", scene.domain.cell);
  h = io::fnv1a64(cell, h);
  const auto addMesh = [&h](const sim::Shape& shape) {
    if (const auto* mesh = std::get_if<sim::MeshFile>(&shape))
      h = io::fnv1a64(fileBytes(mesh->file), h);
  };
  for (const sim::LiquidRegion& r : scene.liquid) addMesh(r.shape);
  for (const sim::Solid& s : scene.solids) addMesh(s.shape);
  return io::hexDigits(io::fnv1a64(versionText(), h));
}

/// The frames simulate writes for `run` (all of them, VDB only), named relative to OUTDIR.
std::vector<std::string> frameFiles(const sim::Scene& scene) {
  const int last = static_cast<int>(std::lround(scene.time.duration * scene.time.fps));
  std::vector<std::string> files;
  for (int f = 0; f <= last; ++f) files.push_back("frames/" + io::frameFileName(f, "vdb"));
  return files;
}

/// The name of the audio file: the scene file's name without `.json` and `.scene`, with the
/// extension of the format asked for (`.wav` by default).
std::string audioName(const std::filesystem::path& scene, const AudioOutputOptions& audio) {
  std::string stem = scene.stem().string();
  if (stem.size() > 6 && stem.ends_with(".scene")) stem.resize(stem.size() - 6);
  const bool flac = audio.format == "flac" || audio.format == "FLAC";
  return stem + (flac ? ".flac" : ".wav");
}

/// Checks, before the first frame, that each file the run writes into an existing OUTDIR could be
/// written (a new OUTDIR is made by simulate), so that no later stage fails on it after the
/// simulation.
void requireRunOutputs(const std::filesystem::path& out, const std::string& audio) {
  std::error_code ec;
  if (!std::filesystem::is_directory(out, ec)) return;
  for (const std::string& name :
       {std::string("stages.json"), std::string("report.json"), std::string("bubbles.json"),
        std::string("transfer.report.json"), audio, std::string("spectrogram.png"),
        std::string("synth.report.json")})
    io::requireWritableFolder(out / name);
}

/// Bubble counts by radius, 10 log-spaced bins from 0.1 to 10 mm (radii outside go to the ends).
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
/// Welch segment of the measured spectrum: 16384 samples (2.93 Hz bins at 48 kHz); the centroid
/// does not depend on it (Parseval: any segment length holds the record's energy; 4096 … 32768
/// move the pour's centroid by < 0.01 %).
constexpr std::size_t kSpectrumSegmentSamples = 16384;
/// Band of the centroid [Hz]: the audible range, or up to Nyquist if that is lower.
constexpr double kCentroidLowHz = 20.0, kCentroidHighHz = 20000.0;

/// Per listener, the rendered audio's spectral centroid and the one predicted from the bubble
/// tracks (acoustics/analysis/centroid_prediction.h, docs/synthesis.md "What the spectrum shows"); null
/// where a channel has no energy in the band.
Json spectrumSummary(const acoustics::BubbleTrackSet& tracks,
                     const std::filesystem::path& audioPath,
                     const std::optional<double>& sampleRate) {
  const io::AudioBuffer audio = io::readAudio(audioPath);
  // What the synth stage renders with: its rate, the file's duration.
  acoustics::SynthesisSettings settings;
  settings.sampleRate = sampleRate.value_or(tracks.sampleRate);
  settings.duration = tracks.duration;
  const acoustics::FrequencyBand band{kCentroidLowHz, std::min(kCentroidHighHz, audio.sampleRate / 2.0)};
  const std::vector<acoustics::PredictedSpectrum> predicted = acoustics::predictedSpectra(tracks, settings, band);
  Json channels = Json::array();
  for (std::size_t l = 0; l < audio.channels.size(); ++l) {
    Json measured = nullptr;
    if (audio.frameCount() > 0) {
      const acoustics::PowerSpectrum spectrum =
          acoustics::welchPowerSpectrum(audio.channels[l], audio.sampleRate, kSpectrumSegmentSamples);
      double power = 0.0;
      for (std::size_t k = 0; k < spectrum.power.size(); ++k)
        if (spectrum.frequency(k) >= band.low && spectrum.frequency(k) <= band.high) power += spectrum.power[k];
      if (power > 0.0) measured = acoustics::spectralCentroid(spectrum, band);
    }
    const bool heard = l < predicted.size() && predicted[l].bandEnergy > 0.0;
    Json channel = {{"channel", l}};
    if (l < tracks.listeners.size()) channel["listener"] = tracks.listeners[l];
    channel["centroid_measured_hz"] = measured;
    channel["centroid_predicted_hz"] = heard ? Json(predicted[l].centroid) : Json(nullptr);
    channels.push_back(channel);
  }
  return {{"band_hz", {band.low, band.high}}, {"channels", channels}};
}

/// After a signal in a stage: OUTDIR/report.json says `"complete": false` and where the run
/// stopped (simulate marks its own; a later stage marks the report it started from).
io::Interrupted markRunIncomplete(const std::filesystem::path& out, const io::Interrupted& signal) {
  if (!signal.aftermath().empty()) return signal;
  const std::filesystem::path path = out / "report.json";
  Json report = Json::parse(fileBytes(path), nullptr, false);
  if (!report.is_object()) report = {{"format", "fluidsound.report/1"}, {"command", "run"}};
  report["complete"] = false;
  report["interrupted_at"] = signal.where();
  io::writeTextFile(path, jsonFileText(report));
  return io::Interrupted(signal.signalNumber(), signal.where(), path.string() + " marked incomplete");
}

int runStages(const RunOptions& o) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  // Bad input (the scene, --cell) stops here, before any output.
  const sim::Scene scene = sceneAtCellSize(io::readScene(o.scene), o.cell);
  requireMemoryForGrid(scene, o.scene, o.cell, physicalMemoryBytes());
  requireMemoryForRender(scene, o.scene, physicalMemoryBytes());
  const std::string hash = inputHash(scene);
  const std::filesystem::path out = o.output;
  const std::string audioFile = audioName(scene.file, o.audio);
  requireRunOutputs(out, audioFile);
  StageRecords records(out, {"simulate", "transfer", "synth", "report"}, o.fresh);
  Json stageReport = Json::object();
  // Runs `stage` unless its record shows it complete (stage_records.h: same inputs, the files it
  // reads as their producer left them, every artefact present and unchanged), then records what it
  // read and wrote, so that an interrupted or damaged run redoes exactly the stages it must.
  // `stageHash` is the stage's own input hash: the scene's, for transfer also the oscillator model
  // (it gives ω), for synth the model and the audio options.
  const auto runStage = [&](const char* name, const std::vector<std::string>& reads, const auto& body,
                            const std::vector<std::string>& artefacts, const std::string& stageHash) {
    const std::string reason = records.reasonToRun(name, stageHash, reads, artefacts);
    const auto t0 = Clock::now();
    if (!reason.empty()) {
      if (!o.common.quiet) std::fprintf(stderr, "run: %s (%s)\n", name, reason.c_str());
      FileDigests before;  // taken first: transfer rewrites the bubbles.json it reads
      for (const std::string& file : reads)
        if (const auto digest = records.inputDigest(name, file)) before[file] = *digest;
      records.forget(name);
      body();
      records.complete(name, stageHash, std::move(before), artefacts);
    } else if (!o.common.quiet) {
      std::fprintf(stderr, "run: %s — up to date, reused\n", name);
    }
    stageReport[name] = {{"reused", reason.empty()},
                         {"seconds", std::chrono::duration<double>(Clock::now() - t0).count()}};
    if (!reason.empty()) stageReport[name]["reason"] = reason;
  };
  const std::vector<std::string> frames = frameFiles(scene);

  SimulateOptions simulate;
  simulate.common = o.common;
  simulate.scene = o.scene;
  simulate.output = o.output;
  simulate.cell = o.cell;
  std::vector<std::string> simulated = frames;
  simulated.insert(simulated.end(), {"bubbles.json", "report.json"});
  runStage(
      "simulate", {}, [&] { runSimulateCommand(simulate); }, simulated, hash);
  // simulate's report.json is the base of the run's report; read it before later stages change
  // anything (a reused simulation keeps its own).
  Json report = Json::parse(fileBytes(out / "report.json"), nullptr, false);
  if (!report.is_object()) report = Json::object();

  TransferOptions transfer;
  transfer.common = o.common;
  transfer.scene = o.scene;
  transfer.output = o.output;
  transfer.model = o.model;
  std::vector<std::string> transferReads = frames;
  transferReads.push_back("bubbles.json");
  const std::string modelHash = hash + " " + oscillatorModelFingerprint(o.model);
  runStage("transfer", transferReads, [&] { runTransferCommand(transfer); },
           {"bubbles.json", "transfer.report.json"}, modelHash);

  SynthOptions synth;
  synth.common = o.common;
  synth.input = (out / "bubbles.json").string();
  synth.audio = o.audio;
  synth.output = (out / audioFile).string();
  synth.spectrogram = (out / "spectrogram.png").string();
  synth.report = (out / "synth.report.json").string();
  synth.model = o.model;
  // The synth stage also depends on the audio options: a new --loudness renders again.
  runStage("synth", {"bubbles.json"}, [&] { runSynthCommand(synth); },
           {audioFile, "spectrogram.png", "synth.report.json"},
           modelHash + " " + audioOptionsFingerprint(o.audio));

  const acoustics::BubbleTrackSet tracks = io::readBubbleTracks(out / "bubbles.json");
  const Json synthReport = Json::parse(fileBytes(out / "synth.report.json"), nullptr, false);
  Json run = {{"scene", o.scene},
              {"cell_size", scene.domain.cell},
              {"input_hash", hash},
              {"stages", stageReport},
              {"bubbles", tracks.bubbles.size()},
              {"radius_histogram", radiusHistogram(tracks)},
              {"audio", audioFile},
              {"spectrogram", "spectrogram.png"},
              {"seconds", std::chrono::duration<double>(Clock::now() - start).count()}};
  if (synthReport.is_object() && synthReport.contains("results")) {
    const Json& r = synthReport["results"];
    if (r.contains("peak_pascals")) run["peak_pascals"] = r["peak_pascals"];
    if (r.contains("output_peak_dbfs")) run["peak_dbfs"] = r["output_peak_dbfs"];
    if (r.contains("oscillator_kernel")) run["oscillator_kernel"] = r["oscillator_kernel"];
    if (r.contains("audio_output"))
      run["audio_output"] = r["audio_output"];  // scale, gain, loudness, names
  }
  run["spectrum"] = spectrumSummary(tracks, out / audioFile, o.audio.sampleRate);
  report["run"] = run;
  report["complete"] = true;  // also over the mark an interrupted earlier run left
  report.erase("interrupted_at");
  io::throwIfInterrupted("run, before writing report.json");
  // The run's report.json is simulate's plus `run`: recorded as made from simulate's, so that
  // simulate's artefact still counts as intact next time.
  const std::optional<io::FileDigest> simulateReport =
      records.recordedArtefact("simulate", "report.json");
  io::writeTextFile(out / "report.json", jsonFileText(report));
  if (simulateReport)
    records.complete("report", hash, {{"report.json", *simulateReport}}, {"report.json"});
  if (!o.common.quiet)
    std::fprintf(stderr, "run: %zu bubbles -> %s, spectrogram.png, report.json (%.1f s)\n",
                 tracks.bubbles.size(), (out / audioFile).string().c_str(),
                 run["seconds"].get<double>());
  return kExitSuccess;
}
}  // namespace

int runRunCommand(const RunOptions& o) {
  try {
    return runStages(o);
  } catch (const io::Interrupted& signal) {
    throw markRunIncomplete(o.output, signal);
  }
}

}  // namespace fluidsound::tools
