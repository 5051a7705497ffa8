// tools/simulate_command.cpp — `fluidsound simulate` (see simulate_command.h, docs/cli.md).
#include "tools/simulate_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "io/bubble_histories.h"
#include "io/bubble_track_file.h"
#include "io/frame_files.h"
#include "io/frame_folder.h"
#include "io/input_error.h"
#include "io/interruption.h"
#include "io/scene_file.h"
#include "io/scene_meshes.h"
#include "io/text_file.h"
#include "sim/simulation.h"
#include "sim/fluid/simulation_failure.h"
#include "tools/cell_option.h"
#include "tools/solver_memory.h"
#include "tools/progress_display.h"
#include "tools/run_report.h"

namespace fluidsound::tools {

CLI::App* addSimulateCommand(CLI::App& app, SimulateOptions& o) {
  CLI::App* c = app.add_subcommand("simulate", "simulate a scene's liquid: frames/NNNN.vdb and report.json");
  c->add_option("scene", o.scene, "scene file (fluidsound.scene/1)")->required();
  c->add_option("-o,--output", o.output, "output folder")->required();
  c->add_option("--frames", o.frames, "frames A:B to write (inclusive; default all)");
  c->add_flag("--ply", o.ply, "also write frames/NNNN.ply with the particles");
  addCellOption(*c, o.cell);
  addCommonOptions(*c, o.common);
  return c;
}

namespace {

struct FrameRange {
  int first = 0, last = 0;
};

FrameRange parseFrames(const std::string& text, int total) {
  if (text.empty()) return {0, total};
  const auto colon = text.find(':');
  try {
    if (colon == std::string::npos) throw std::invalid_argument(text);
    const int a = std::stoi(text.substr(0, colon)), b = std::stoi(text.substr(colon + 1));
    if (a < 0 || b < a || b > total) throw std::invalid_argument(text);
    return {a, b};
  } catch (const std::exception&) {
    throw CLI::ValidationError("--frames", "expected A:B with 0 ≤ A ≤ B ≤ " + std::to_string(total) + ", found " + text);
  }
}

std::string frameName(int frame, const char* extension) {
  return io::frameFileName(frame, extension);
}

/// Clears the frames another run left in `frames` (io/frame_folder.h), so that it holds only the
/// frames this one writes beside its bubbles.json; says what it removed and warns of what it left.
void clearOtherRunsFrames(const std::filesystem::path& frames, const FrameRange& range, bool ply,
                          bool quiet) {
  const io::FrameFolderCleanup cleanup =
      io::clearStaleFrames(frames, [&](int frame, std::string_view extension) {
        return frame >= range.first && frame <= range.last && (extension == "vdb" || ply);
      });
  if (!cleanup.removed.empty() && !quiet)
    std::fprintf(stderr, "fluidsound: note: %s: removed %zu stale frame file(s) of another run\n",
                 frames.string().c_str(), cleanup.removed.size());
  if (!cleanup.foreign.empty()) {
    std::string names;
    for (std::size_t i = 0; i < cleanup.foreign.size() && i < 3; ++i)
      names += (i > 0 ? ", " : "") + cleanup.foreign[i].filename().string();
    std::fprintf(
        stderr, "fluidsound: warning: %s: left %zu entr%s that %s not frames of this run: %s%s\n",
        frames.string().c_str(), cleanup.foreign.size(), cleanup.foreign.size() == 1 ? "y" : "ies",
        cleanup.foreign.size() == 1 ? "is" : "are", names.c_str(),
        cleanup.foreign.size() > 3 ? ", ..." : "");
  }
}

/// The simulation's observer for the CLI: writes the kept frames (VDB, and PLY with --ply), logs
/// a line per frame and shows progress; a signal (io/interruption.h) interrupts the simulation.
class FrameWriter : public sim::SimulationObserver {
 public:
  FrameWriter(std::filesystem::path frames, bool ply, int last, bool quiet)
      : frames_(std::move(frames)), ply_(ply), last_(last), progress_("simulate", last + 1, "frames", quiet) {}

  void onFrame(const sim::FrameView& state, const sim::FrameRecord& record) override {
    const auto t0 = std::chrono::steady_clock::now();
    if (state.kept) {
      try {  // a frame for a FIFO waits for its reader, until a signal
        io::writeFrameVdb(frames_ / frameName(record.frame, "vdb"), state.grid, state.particles, state.velocity,
                          {state.particleRadius});
        if (ply_) io::writeParticlesPly(frames_ / frameName(record.frame, "ply"), state.particles);
      } catch (const io::Interrupted& signal) {
        unwritten_.emplace(record.frame, signal);
        return;
      }
    }
    const double seconds =
        record.simulationSeconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    char line[160];  // through the display, which clears its line first on a terminal
    std::snprintf(line, sizeof line,
                  "frame %4d/%d  t %.3f s  substeps %2d  cg %4d (res %.1e)  particles %zu  %.2f s", record.frame,
                  last_, record.time, record.fluid.substeps, record.fluid.pressureIterations,
                  record.fluid.pressureResidual, record.particles, seconds);
    progress_.log(line);
  }
  void progress(double fraction) override { progress_.update(fraction); }
  bool wasInterrupted() override { return io::interruptionRequested(); }
  void finish() { progress_.finish(); }
  /// The frame whose writing a signal ended, and the signal (the simulation stopped after it).
  const std::optional<std::pair<int, io::Interrupted>>& unwritten() const { return unwritten_; }

 private:
  std::filesystem::path frames_;
  bool ply_;
  int last_;
  ProgressDisplay progress_;
  std::optional<std::pair<int, io::Interrupted>> unwritten_;
};

/// report.json's `results.frames`: one object per frame made (docs/cli.md).
nlohmann::ordered_json framesJson(const std::vector<sim::FrameRecord>& records) {
  nlohmann::ordered_json frames = nlohmann::ordered_json::array();
  for (const sim::FrameRecord& r : records) {
    const sim::FrameStats& s = r.fluid;
    frames.push_back({{"frame", r.frame}, {"time", r.time}, {"substeps", s.substeps},
                      {"cg_iterations", s.pressureIterations}, {"cg_residual", s.pressureResidual},
                      {"cg_converged", s.pressureConverged}, {"particles", r.particles},
                      {"particles_deleted", s.particlesDeleted}, {"particles_emitted", s.particlesEmitted},
                      {"particles_reseeded", s.particlesReseeded}, {"particles_thinned", s.particlesThinned},
                      {"density_cg_iterations", s.densityIterations}, {"max_density_excess", s.maxDensityExcess},
                      {"liquid_volume", s.liquidVolume}, {"max_divergence", s.maxDivergence},
                      {"max_speed", s.maxSpeed}, {"bubbles_alive", r.bubblesAlive},
                      {"bubbles_total", r.bubblesTotal}, {"seconds", r.simulationSeconds + r.observerSeconds}});
  }
  return frames;
}

}  // namespace

int runSimulateCommand(const SimulateOptions& o) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  // The cell size is final before the meshes load: their node distances are sampled on its grid.
  sim::Scene scene = sceneAtCellSize(io::readScene(o.scene), o.cell);
  requireMemoryForGrid(scene, o.scene, o.cell, physicalMemoryBytes());
  io::loadSceneMeshes(scene);
  const FrameRange range = parseFrames(o.frames, sim::lastSceneFrame(scene));
  const std::filesystem::path out = o.output, frames = out / "frames";
  // Both outputs are checked before the frames folder is made, so a failure leaves nothing new.
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) throw io::OutputError(out.string() + ": cannot create the folder: " + ec.message());
  io::requireWritableFolder(out / "report.json");
  io::requireWritableFolder(out / "bubbles.json");
  std::filesystem::create_directories(frames, ec);
  if (ec) throw io::OutputError(frames.string() + ": cannot create the folder: " + ec.message());
  io::requireWritableFolder(frames / "0000.vdb");
  clearOtherRunsFrames(frames, range, o.ply, o.common.quiet);

  FrameWriter writer(frames, o.ply, range.last, o.common.quiet);
  sim::SimulationResult result;
  try {
    result = sim::simulate(scene, {range.first, range.last}, writer);
  } catch (const sim::SubstepLimitError& e) {  // bad input: the scene asks for what cannot end
    throw io::InputError(o.scene, e.likelyFields(),
                         "a frame that ends within " + std::to_string(sim::kMaxSubstepsPerFrame) + " substeps",
                         e.what());
  } catch (const sim::SimulationFailure& e) {  // one line: the scene, the frame, where
    throw sim::SimulationFailure(o.scene + ": " + e.what());
  }
  writer.finish();
  // A signal ends the frames (each written one is whole); the report then says where it ended.
  std::optional<io::Interrupted> interrupted;
  if (writer.unwritten()) {  // the report lists the frames before it, as for a signal in a frame
    interrupted = writer.unwritten()->second;
    std::erase_if(result.frames, [&](const sim::FrameRecord& r) { return r.frame >= writer.unwritten()->first; });
  } else if (result.interrupted) {
    interrupted.emplace(io::interruptionSignal(), "simulate frame " + std::to_string(result.interrupted->frame));
  }
  const auto w0 = Clock::now();
  if (!interrupted) io::writeBubbleTracks(out / "bubbles.json", io::bubbleTracksFromHistories(result.bubbles, scene));
  const double writeSeconds = result.observerSeconds + std::chrono::duration<double>(Clock::now() - w0).count();

  RunReport report("simulate");
  report.setting("scene", o.scene);
  report.setting("output", o.output);
  report.setting("cells", static_cast<double>(result.grid.cells[0]) * result.grid.cells[1] * result.grid.cells[2]);
  report.setting("cell_size", result.grid.cellSize);
  report.setting("fps", scene.time.fps);
  report.setting("cfl", scene.time.cfl);
  report.setting("seed", static_cast<double>(scene.seed));
  report.stageSeconds("simulation", result.simulationSeconds);
  report.stageSeconds("bubbles", result.bubbleSeconds);
  report.stageSeconds("output", writeSeconds);
  report.resultJson("frames", framesJson(result.frames).dump());
  report.result("bubbles", static_cast<double>(result.bubbles.size()));
  report.result("seconds", std::chrono::duration<double>(Clock::now() - start).count());
  if (interrupted) report.markIncomplete(interrupted->where());
  report.write(out / "report.json");
  if (interrupted)
    throw io::Interrupted(interrupted->signalNumber(), interrupted->where(),
                          (out / "report.json").string() + " marked incomplete");
  return kExitSuccess;
}

}  // namespace fluidsound::tools
