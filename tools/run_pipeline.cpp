// tools/run_pipeline.cpp — see run_pipeline.h.
#include "tools/run_pipeline.h"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include "io/bubble_track_file.h"
#include "io/input_error.h"
#include "io/scene_file.h"
#include "io/text_file.h"
#include "tools/cell_option.h"
#include "tools/render_memory.h"
#include "tools/run_inputs.h"
#include "tools/run_playback.h"
#include "tools/run_report.h"
#include "tools/run_solids.h"
#include "tools/run_summary.h"
#include "tools/simulate_command.h"
#include "tools/solver_memory.h"
#include "tools/synth_command.h"
#include "tools/transfer_choice.h"
#include "tools/transfer_command.h"
#include "tools/transfer_report.h"

namespace fluidsound::tools {

using Json = nlohmann::ordered_json;

namespace {

/// The scene at its run's cell size, refused if its grid or its audio would not fit in memory or
/// a file the run writes could not be written: bad input stops here, before any output.
sim::Scene checkedScene(const RunOptions& o) {
  sim::Scene scene = sceneAtCellSize(io::readScene(o.scene), o.cell);
  readCollisionRecordings(scene);  // a missing or unreadable recording is bad input: refused now
  requireMemoryForGrid(scene, o.scene, o.cell, physicalMemoryBytes());
  requireMemoryForRender(scene, o.scene, physicalMemoryBytes());
  requireRunOutputs(o.output, audioName(scene.file, o.audio));
  return scene;
}

/// OUTDIR/stems, made if missing; anything else of that name is refused, not replaced.
void createStemFolder(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder))
    throw io::OutputError(folder.string() + ": cannot make the stems' folder: " +
                          (ec ? ec.message() : std::string("not a folder")));
}

}  // namespace

RunPipeline::RunPipeline(const RunOptions& o)
    : o_(o),
      start_(Clock::now()),
      scene_(checkedScene(o)),
      hash_(inputHash(scene_)),
      modelHash_(hash_ + " " + oscillatorModelFingerprint(o.model)),
      transferHash_(modelHash_ + " " +
                    transferChoiceFingerprint(transferChoice(scene_, o.transfer))),
      audioFile_(audioName(scene_.file, o.audio)),
      out_(o.output),
      frames_(frameFiles(scene_)),
      records_(out_, {"simulate", "transfer", "synth", "report"}, o.fresh) {}

bool RunPipeline::runStage(const StagePlan& plan, const std::function<void()>& body) {
  const std::string reason =
      records_.reasonToRun(plan.name, plan.inputHash, plan.reads, plan.artefacts);
  const auto t0 = Clock::now();
  if (!reason.empty()) {
    if (!o_.common.quiet) std::fprintf(stderr, "run: %s (%s)\n", plan.name, reason.c_str());
    FileDigests before;  // taken first: transfer rewrites the bubbles.json it reads
    for (const std::string& file : plan.reads)
      if (const auto digest = records_.inputDigest(plan.name, file)) before[file] = *digest;
    records_.forget(plan.name);
    body();
    records_.complete(plan.name, plan.inputHash, std::move(before), plan.artefacts);
  } else if (!o_.common.quiet) {
    std::fprintf(stderr, "run: %s — up to date, reused\n", plan.name);
  }
  stages_[plan.name] = {{"reused", reason.empty()},
                        {"seconds", std::chrono::duration<double>(Clock::now() - t0).count()}};
  if (!reason.empty()) stages_[plan.name]["reason"] = reason;
  return !reason.empty();
}

void RunPipeline::simulate() {
  const SimulateOptions simulate{.common = o_.common,
                                 .scene = o_.scene,
                                 .output = o_.output,
                                 .frames = {},  // all
                                 .ply = false,
                                 .cell = o_.cell};
  std::vector<std::string> artefacts = frames_;
  artefacts.insert(artefacts.end(), {"bubbles.json", "report.json"});
  if (!scene_.bodies.empty()) artefacts.push_back("contacts.bin");
  const bool ran = runStage({"simulate", {}, artefacts, hash_}, [&] {
    SimulateOutcome outcome = simulateIntoFolder(simulate);
    tracks_ = std::move(outcome.tracks);
    report_ = std::move(outcome.report);
  });
  if (!ran) report_ = Json::parse(fileBytes(out_ / "report.json"), nullptr, false);
  if (!report_.is_object()) report_ = Json::object();
}

void RunPipeline::transfer() {
  const TransferOptions transfer{.common = o_.common,
                                 .scene = o_.scene,
                                 .output = o_.output,
                                 .model = o_.model,
                                 .transfer = o_.transfer};
  std::vector<std::string> reads = frames_;
  reads.push_back("bubbles.json");
  const bool ran = runStage(
      {"transfer", reads, {"bubbles.json", "transfer.report.json"}, transferHash_},
      [&] { tracks_ = transferInFolder(transfer, scene_, std::exchange(tracks_, std::nullopt)); });
  if (!ran) tracks_.reset();  // its bubbles.json holds the tracks, not simulate's in memory
  transferReport_ = Json::parse(fileBytes(out_ / "transfer.report.json"), nullptr, false);
}

void RunPipeline::synth() {
  const SynthOptions synth{.common = o_.common,
                           .input = (out_ / "bubbles.json").string(),
                           .output = (out_ / audioFile_).string(),
                           .audio = o_.audio,
                           .duration = {},  // the file's
                           .report = (out_ / "synth.report.json").string(),
                           .spectrogram = (out_ / "spectrogram.png").string(),
                           .model = o_.model};
  // The synth stage also depends on the audio options: a new --loudness renders again.
  std::vector<std::string> artefacts = {audioFile_, "spectrogram.png", "synth.report.json"};
  std::vector<std::string> reads = {"bubbles.json"};
  // With bodies, the solids' stems are mixed in and every stem is written (tools/run_solids.h).
  std::optional<MixedSources> mixed;
  if (!scene_.bodies.empty()) {
    reads.push_back("contacts.bin");
    for (const char* stem : {"bubbles", "impacts", "rolling", "friction"})
      artefacts.push_back(std::string("stems/") + stem + ".wav");
    mixed = MixedSources{[this](std::size_t frames, double rate) {
                           return o_.solids == "samples"
                                      ? renderRunPlayback(scene_, out_, frames, rate, o_.common.quiet)
                                      : renderRunSolids(scene_, out_, frames, rate, o_.common.quiet);
                         },
                         out_ / "stems"};
  }
  const bool ran = runStage(
      {"synth", reads, artefacts, modelHash_ + " " + audioOptionsFingerprint(o_.audio) + " solids " + o_.solids}, [&] {
        if (mixed) createStemFolder(mixed->stemFolder);
        synthReport_ = renderSynth(synth, tracks_ ? &*tracks_ : nullptr, mixed ? &*mixed : nullptr);
      });
  if (!ran) synthReport_ = Json::parse(fileBytes(out_ / "synth.report.json"), nullptr, false);
}

void RunPipeline::writeReport() {
  const acoustics::BubbleTrackSet tracks =
      tracks_ ? std::move(*tracks_) : io::readBubbleTracks(out_ / "bubbles.json");
  Json run = {{"scene", o_.scene},
              {"cell_size", scene_.domain.cell},
              {"input_hash", hash_},
              {"stages", stages_},
              {"bubbles", tracks.bubbles.size()},
              {"radius_histogram", radiusHistogram(tracks)},
              {"audio", audioFile_},
              {"spectrogram", "spectrogram.png"},
              {"seconds", std::chrono::duration<double>(Clock::now() - start_).count()}};
  run["transfer"] = transferSummary(transferReport_);
  addSynthSummary(run, synthReport_);
  run["spectrum"] = spectrumSummary(tracks, out_ / audioFile_, o_.audio.sampleRate);
  report_["run"] = run;
  report_["complete"] = true;  // also over the mark an interrupted earlier run left
  report_.erase("interrupted_at");
  io::throwIfInterrupted("run, before writing report.json");
  // The run's report.json is simulate's plus `run`: recorded as made from simulate's, so that
  // simulate's artefact still counts as intact next time.
  const std::optional<io::FileDigest> simulateReport =
      records_.recordedArtefact("simulate", "report.json");
  io::writeTextFile(out_ / "report.json", jsonFileText(report_));
  if (simulateReport)
    records_.complete("report", hash_, {{"report.json", *simulateReport}}, {"report.json"});
  if (!o_.common.quiet)
    std::fprintf(stderr, "run: %zu bubbles -> %s, spectrogram.png, report.json (%.1f s)\n",
                 tracks.bubbles.size(), (out_ / audioFile_).string().c_str(),
                 run["seconds"].get<double>());
}

io::Interrupted RunPipeline::markIncomplete(const io::Interrupted& signal) {
  if (!signal.aftermath().empty()) return signal;
  Json report = report_.is_object() && !report_.empty()
                    ? report_
                    : Json{{"format", "fluidsound.report/1"}, {"command", "run"}};
  report["complete"] = false;
  report["interrupted_at"] = signal.where();
  const std::filesystem::path path = out_ / "report.json";
  io::writeTextFile(path, jsonFileText(report));
  return io::Interrupted(signal.signalNumber(), signal.where(),
                         path.string() + " marked incomplete");
}

void RunPipeline::run() {
  try {
    simulate();
    transfer();
    synth();
    writeReport();
  } catch (const io::Interrupted& signal) {
    throw markIncomplete(signal);
  }
}

}  // namespace fluidsound::tools
