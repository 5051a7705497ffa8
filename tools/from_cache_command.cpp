// tools/from_cache_command.cpp — see from_cache_command.h.
#include "tools/from_cache_command.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/bubble_histories.h"
#include "io/bubble_track_file.h"
#include "io/cache_file.h"
#include "io/cache_liquid_frames.h"
#include "io/frame_files.h"
#include "io/frame_folder.h"
#include "io/frame_sequence.h"
#include "io/input_error.h"
#include "io/interruption.h"
#include "io/scene_meshes.h"
#include "io/text_file.h"
#include "sim/cache_bubbles.h"
#include "tools/frame_writer.h"
#include "tools/progress_display.h"
#include "tools/render_memory.h"
#include "tools/run_inputs.h"
#include "tools/run_report.h"
#include "tools/run_summary.h"
#include "tools/solver_memory.h"
#include "tools/synth_command.h"
#include "tools/transfer_choice.h"
#include "tools/transfer_command.h"

namespace fluidsound::tools {

using Json = nlohmann::ordered_json;

CLI::App* addFromCacheCommand(CLI::App& app, FromCacheOptions& o) {
  CLI::App* c = app.add_subcommand(
      "from-cache", "the sound of a liquid simulated elsewhere (OpenVDB frames: Houdini, Blender, simulate): "
                    "bubbles -> transfer -> synth, to NAME.wav, spectrogram.png and report.json");
  c->add_option("cache", o.cache, "cache file (fluidsound.cache/1)")->required();
  c->add_option("-o,--output", o.output, "output folder")->required();
  addAudioOutputOptions(*c, o.audio);
  addTransferModelOption(*c, o.transfer);
  addOscillatorModelOptions(*c, o.model);
  addCommonOptions(*c, o.common);
  return c;
}

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// The level set's band written into OUTDIR's frames [voxels] (as simulate's).
constexpr int kFrameBandVoxels = 3;

/// The cache's scene with what its frames give: the domain (the import's grid; the container's
/// closed faces, without one every face open),
/// the time (frame 0 at 0 s, the last at (count − 1)/fps) and, unless the cache names listeners,
/// one 0.5 m above the liquid's centre (a scene's default).
sim::Scene sceneOfCache(const io::CacheDescription& cache, const sim::GridGeometry& grid, int frames) {
  sim::Scene scene = cache.scene;
  scene.domain.min = grid.origin;
  for (int a = 0; a < 3; ++a) scene.domain.max[a] = grid.origin[a] + grid.cells[a] * grid.cellSize;
  scene.domain.cell = grid.cellSize;
  scene.domain.open.fill(true);  // no container: no walls, a bubble leaving the grid ends
  if (cache.container) scene.domain.open = cache.container->open;
  scene.time.fps = cache.fps;
  scene.time.duration = (frames - 1) / cache.fps;
  if (cache.defaultListener) {
    sim::Listener listener{"listener", {}, std::nullopt};
    for (int a = 0; a < 3; ++a) listener.position[a] = 0.5 * (scene.domain.min[a] + scene.domain.max[a]);
    listener.position[1] += 0.5;
    scene.listeners = {listener};
  }
  return scene;
}

/// Refuses an OUTDIR whose frames/ folder is the cache's own frame folder: writing the import's
/// frames there would replace the input.
void requireOutputApartFromCache(const std::filesystem::path& out, const std::vector<io::SequenceFrame>& frames,
                                 const io::CacheDescription& cache) {
  std::error_code error;
  const std::filesystem::path inputFolder = frames.front().path.parent_path();
  if (std::filesystem::exists(out / "frames", error) &&
      std::filesystem::equivalent(out / "frames", inputFolder.empty() ? "." : inputFolder, error))
    throw io::InputError(cache.file.string(), "frames",
                         "frames in another folder than OUTDIR/frames, which from-cache writes",
                         (out / "frames").string() + " (choose another -o)");
}

/// Writes each frame the import read into OUTDIR/frames (its level set and velocity on the
/// import's grid, in metres with y up: what the transfer stage reads) and shows progress.
class ImportObserver : public sim::CacheBubbleObserver {
 public:
  ImportObserver(std::filesystem::path frames, const sim::GridGeometry& grid, double fps, int count, bool quiet)
      : frames_(std::move(frames)), grid_(grid), fps_(fps), progress_("bubbles", count, "frames", quiet) {}
  void onFrame(const sim::LiquidFrame& frame, const sim::CacheFrameRecord& record) override {
    const auto t0 = Clock::now();
    const std::filesystem::path path = frames_ / io::frameFileName(record.frame, "vdb");
    io::writeLevelSetFrameVdb(path, grid_, frame.liquidDistance, frame.velocity, kFrameBandVoxels,
                              {record.frame, record.time, fps_, std::string("fluidsound ") + FLUIDSOUND_VERSION});
    written.push_back(path);
    writeSeconds += secondsSince(t0);
  }
  void progress(double fraction) override { progress_.update(fraction); }
  bool wasInterrupted() override { return io::interruptionRequested(); }
  void finish() { progress_.finish(); }
  /// Removes the frames this run wrote (after a bad frame: nothing half-written stays).
  void removeWritten() {
    std::error_code ignored;
    for (const std::filesystem::path& path : written) std::filesystem::remove(path, ignored);
    written.clear();
  }
  double writeSeconds = 0.0;
  std::vector<std::filesystem::path> written;

 private:
  std::filesystem::path frames_;
  const sim::GridGeometry& grid_;
  double fps_;
  ProgressDisplay progress_;
};

Json frameRecords(const sim::CacheBubbleResult& result) {
  Json frames = Json::array();
  for (const sim::CacheFrameRecord& r : result.frames)
    frames.push_back({{"frame", r.frame},
                      {"time", r.time},
                      {"particles", r.particles},
                      {"particles_followed", r.followed},
                      {"substeps", r.substeps},
                      {"bubbles_alive", r.bubblesAlive},
                      {"bubbles_total", r.bubblesTotal},
                      {"read_seconds", r.readSeconds},
                      {"bubble_seconds", r.bubbleSeconds}});
  return frames;
}

}  // namespace

int runFromCacheCommand(const FromCacheOptions& o) {
  const auto start = Clock::now();
  const io::CacheDescription cache = io::readCacheFile(o.cache);
  const std::filesystem::path folder = cache.file.parent_path();
  const std::vector<io::SequenceFrame> frames = io::frameSequence(cache.frames, folder, cache.file.string(), "frames");
  std::vector<io::SequenceFrame> particles;
  if (cache.particles) {
    particles = io::frameSequence(*cache.particles, folder, cache.file.string(), "particles");
    if (particles.size() != frames.size() || particles.front().frame != frames.front().frame)
      throw io::InputError(cache.file.string(), "particles",
                           "a particle file for every frame " + std::to_string(frames.front().frame) + " to " +
                               std::to_string(frames.back().frame),
                           "frames " + std::to_string(particles.front().frame) + " to " +
                               std::to_string(particles.back().frame));
  }
  if (frames.size() < 2)
    throw io::InputError(cache.file.string(), "frames", "a sequence of at least 2 frames", "1 frame");
  const auto checkStart = Clock::now();
  const sim::GridGeometry grid = io::cacheGrid(cache, frames);  // checks every frame first
  const double checkSeconds = secondsSince(checkStart);
  sim::Scene scene = sceneOfCache(cache, grid, static_cast<int>(frames.size()));
  requireMemoryForRender(scene, o.cache, physicalMemoryBytes());
  io::loadSceneMeshes(scene);
  const std::filesystem::path out = o.output;
  const std::string audio = audioName(cache.file, o.audio);
  requireOutputApartFromCache(out, frames, cache);
  requireRunOutputs(out, audio);
  prepareFrameFolder(out, {0, static_cast<int>(frames.size()) - 1}, false, o.common.quiet);

  // The bubble model at the cache's rate, writing OUTDIR/frames as it reads.
  io::CacheLiquidFrames source(cache, frames, particles, grid);
  ImportObserver observer(out / "frames", grid, cache.fps, static_cast<int>(frames.size()), o.common.quiet);
  sim::CacheBubbleResult result;
  try {
    result = sim::cacheBubbles(source, grid, scene, {}, observer);
  } catch (const io::InputError&) {  // a frame's particles: the frames were checked before
    observer.finish();
    observer.removeWritten();
    throw;
  }
  observer.finish();
  if (result.interruptedAt) {
    RunReport report("from-cache");
    report.setting("cache", o.cache);
    report.markIncomplete("from-cache frame " + std::to_string(*result.interruptedAt));
    report.write(out / "report.json");
    throw io::Interrupted(io::interruptionSignal(), "from-cache frame " + std::to_string(*result.interruptedAt),
                          (out / "report.json").string() + " marked incomplete");
  }
  acoustics::BubbleTrackSet tracks = io::bubbleTracksFromHistories(result.bubbles, scene);
  io::writeBubbleTracks(out / "bubbles.json", tracks);
  const double bubbleStage = secondsSince(start);

  // The transfer and synth stages, as `run` has them.
  const auto t1 = Clock::now();
  tracks = transferInFolder({.common = o.common, .scene = o.cache, .output = o.output, .model = o.model,
                             .transfer = o.transfer},
                            scene, std::move(tracks));
  const double transferSeconds = secondsSince(t1);
  const auto t2 = Clock::now();
  const Json synthReport = renderSynth({.common = o.common,
                                        .input = (out / "bubbles.json").string(),
                                        .output = (out / audio).string(),
                                        .audio = o.audio,
                                        .duration = {},
                                        .report = (out / "synth.report.json").string(),
                                        .spectrogram = (out / "spectrogram.png").string(),
                                        .model = o.model},
                                       &tracks);
  const double synthSeconds = secondsSince(t2);

  RunReport report("from-cache");
  report.setting("cache", o.cache);
  report.setting("fps", cache.fps);
  report.setting("metres_per_unit", cache.metresPerUnit);
  report.setting("up", cache.up == io::UpAxis::Z ? "z" : "y");
  report.setting("cell_size", grid.cellSize);
  report.stageSeconds("check", checkSeconds);
  report.stageSeconds("read", result.readSeconds);
  report.stageSeconds("bubbles", result.bubbleSeconds);
  report.stageSeconds("output", observer.writeSeconds);
  report.stageSeconds("transfer", transferSeconds);
  report.stageSeconds("synth", synthSeconds);
  report.result("frames", static_cast<double>(frames.size()));
  report.result("bubbles", static_cast<double>(tracks.bubbles.size()));
  report.result("bubble_stage_seconds_per_frame", bubbleStage / static_cast<double>(frames.size()));
  report.result("seconds", secondsSince(start));
  Json document = report.document();
  document["results"]["grid"] = {{"cells", {grid.cells[0], grid.cells[1], grid.cells[2]}},
                                 {"origin", {grid.origin[0], grid.origin[1], grid.origin[2]}},
                                 {"cell_size", grid.cellSize}};
  document["results"]["frames_read"] = frameRecords(result);
  Json run = {{"radius_histogram", radiusHistogram(tracks)}, {"audio", audio}, {"spectrogram", "spectrogram.png"}};
  addSynthSummary(run, synthReport);
  run["spectrum"] = spectrumSummary(tracks, out / audio, o.audio.sampleRate);
  document["run"] = run;
  io::writeTextFile(out / "report.json", jsonFileText(document));
  if (!o.common.quiet)
    std::fprintf(stderr, "from-cache: %zu frames, %zu bubbles -> %s, spectrogram.png, report.json (%.1f s)\n",
                 frames.size(), tracks.bubbles.size(), (out / audio).string().c_str(), secondsSince(start));
  return kExitSuccess;
}

}  // namespace fluidsound::tools
