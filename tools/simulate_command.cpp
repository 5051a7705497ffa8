// tools/simulate_command.cpp — `fluidsound simulate` (see simulate_command.h, docs/cli.md).
#include "tools/simulate_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

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
#include "sim/bubble_model.h"
#include "sim/fluid_solver.h"
#include "sim/simulation_failure.h"
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

}  // namespace

int runSimulateCommand(const SimulateOptions& o) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  // The cell size is final before the meshes load: their node distances are sampled on its grid.
  sim::Scene scene = sceneAtCellSize(io::readScene(o.scene), o.cell);
  requireMemoryForGrid(scene, o.scene, o.cell, physicalMemoryBytes());
  io::loadSceneMeshes(scene);
  const int total = static_cast<int>(std::lround(scene.time.duration * scene.time.fps));
  const FrameRange range = parseFrames(o.frames, total);
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

  sim::FluidSolver solver(scene);
  // The bubble model runs inside the loop on the in-memory state (DESIGN.md), with the scene's
  // `bubbles` block (docs/bubbles.md).
  sim::BubbleModel bubbles(scene.bubbles, scene.seed, scene.gravity);
  int frame = 0;  // the frame being made, named by the message of a signal
  const sim::SubstepObserver stepBubbles = [&bubbles, &frame](const sim::LiquidState& liquid, double t, double dt) {
    io::throwIfInterrupted("simulate frame " + std::to_string(frame));
    bubbles.step(liquid, t, dt);
  };
  double bubbleSeconds = 0.0;
  nlohmann::ordered_json perFrame = nlohmann::ordered_json::array();
  double simulateSeconds = 0.0, writeSeconds = 0.0;
  ProgressDisplay progress("simulate", range.last + 1, "frames", o.common.quiet);
  // A signal ends the frames (each written one is whole); the report then says where it ended.
  std::optional<io::Interrupted> interrupted;
  try {
    for (int f = 0; f <= range.last; ++f) {
      frame = f;
      io::throwIfInterrupted("simulate frame " + std::to_string(f));
      const auto t0 = Clock::now();
      sim::FrameStats stats;
      if (f == 0) {  // the initial state: nothing simulated, but its volume is the reference
        stats.particles = solver.particles().size();
        stats.liquidVolume = solver.liquidVolume();  // outside the solids, as every later frame's
      } else {
        try {
          stats = solver.advanceTo(f / scene.time.fps, stepBubbles);
        } catch (const sim::SubstepLimitError& e) {  // bad input: the scene asks for what cannot end
          throw io::InputError(o.scene, e.likelyFields(),
                               "a frame that ends within " + std::to_string(sim::kMaxSubstepsPerFrame) + " substeps",
                               "frame " + std::to_string(f) + " needs " + e.what());
        } catch (const sim::SimulationFailure& e) {  // one line: the scene, the frame, where
          throw sim::SimulationFailure(o.scene + ": frame " + std::to_string(f) + ": " + e.what());
        }
        const auto s0 = Clock::now();
        bubbles.sampleFrame(solver.time());  // the bubble model's too, not the fluid's
        bubbleSeconds += stats.stageSeconds.bubbles + std::chrono::duration<double>(Clock::now() - s0).count();
      }
      const auto t1 = Clock::now();
      if (f >= range.first) {
        io::writeFrameVdb(frames / frameName(f, "vdb"), solver.grid(), solver.particles(), solver.velocity(),
                          {solver.particleRadius()});
        if (o.ply) io::writeParticlesPly(frames / frameName(f, "ply"), solver.particles());
      }
      const auto t2 = Clock::now();
      const double seconds = std::chrono::duration<double>(t2 - t0).count();
      simulateSeconds += std::chrono::duration<double>(t1 - t0).count();
      writeSeconds += std::chrono::duration<double>(t2 - t1).count();
      perFrame.push_back({{"frame", f}, {"time", solver.time()}, {"substeps", stats.substeps},
                          {"cg_iterations", stats.pressureIterations}, {"cg_residual", stats.pressureResidual},
                          {"cg_converged", stats.pressureConverged}, {"particles", solver.particles().size()},
                          {"particles_deleted", stats.particlesDeleted}, {"particles_emitted", stats.particlesEmitted},
                          {"particles_reseeded", stats.particlesReseeded}, {"particles_thinned", stats.particlesThinned},
                          {"density_cg_iterations", stats.densityIterations},
                          {"max_density_excess", stats.maxDensityExcess},
                          {"liquid_volume", stats.liquidVolume},
                          {"max_divergence", stats.maxDivergence}, {"max_speed", stats.maxSpeed},
                          {"bubbles_alive", bubbles.aliveCount()}, {"bubbles_total", bubbles.bubbles().size()},
                          {"seconds", seconds}});
      char line[160];  // through the display, which clears its line first on a terminal
      std::snprintf(line, sizeof line,
                    "frame %4d/%d  t %.3f s  substeps %2d  cg %4d (res %.1e)  particles %zu  %.2f s",
                    f, range.last, solver.time(), stats.substeps, stats.pressureIterations,
                    stats.pressureResidual, solver.particles().size(), seconds);
      progress.log(line);
      progress.update(static_cast<double>(f + 1) / (range.last + 1));
    }
  } catch (const io::Interrupted& signal) {
    interrupted = signal;
  }
  progress.finish();
  const auto w0 = Clock::now();
  if (!interrupted)
    io::writeBubbleTracks(out / "bubbles.json", io::bubbleTracksFromHistories(bubbles.bubbles(), scene));
  writeSeconds += std::chrono::duration<double>(Clock::now() - w0).count();

  RunReport report("simulate");
  report.setting("scene", o.scene);
  report.setting("output", o.output);
  report.setting("cells", static_cast<double>(solver.grid().cells[0]) * solver.grid().cells[1] * solver.grid().cells[2]);
  report.setting("cell_size", solver.grid().cellSize);
  report.setting("fps", scene.time.fps);
  report.setting("cfl", scene.time.cfl);
  report.setting("seed", static_cast<double>(scene.seed));
  report.stageSeconds("simulation", simulateSeconds - bubbleSeconds);
  report.stageSeconds("bubbles", bubbleSeconds);
  report.stageSeconds("output", writeSeconds);
  report.resultJson("frames", perFrame.dump());
  report.result("bubbles", static_cast<double>(bubbles.bubbles().size()));
  report.result("seconds", std::chrono::duration<double>(Clock::now() - start).count());
  if (interrupted) report.markIncomplete(interrupted->where());
  report.write(out / "report.json");
  if (interrupted)
    throw io::Interrupted(interrupted->signalNumber(), interrupted->where(),
                          (out / "report.json").string() + " marked incomplete");
  return kExitSuccess;
}

}  // namespace fluidsound::tools
