// tools/simulate_command.cpp — `fluidsound simulate` (see simulate_command.h, docs/cli.md).
#include "tools/simulate_command.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "io/bubble_histories.h"
#include "io/bubble_track_file.h"
#include "io/contact_log_file.h"
#include "io/input_error.h"
#include "io/interruption.h"
#include "io/scene_file.h"
#include "io/scene_meshes.h"
#include "io/text_file.h"
#include "sim/fluid/simulation_failure.h"
#include "sim/simulation.h"
#include "tools/cell_option.h"
#include "tools/frame_writer.h"
#include "tools/run_report.h"
#include "tools/simulate_report.h"
#include "tools/solver_memory.h"

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

/// sim::simulate with its failures as the CLI reports them (one line naming the scene).
sim::SimulationResult simulateScene(const sim::Scene& scene, const std::string& sceneFile,
                                    const FrameRange& range, FrameWriter& writer) {
  try {
    return sim::simulate(scene, {range.first, range.last}, writer);
  } catch (const sim::SubstepLimitError& e) {  // bad input: the scene asks for what cannot end
    throw io::InputError(
        sceneFile, e.likelyFields(),
        "a frame that ends within " + std::to_string(sim::kMaxSubstepsPerFrame) + " substeps",
        e.what());
  } catch (const sim::SimulationFailure& e) {  // one line: the scene, the frame, where
    throw sim::SimulationFailure(sceneFile + ": " + e.what());
  }
}

/// What report.json says of the bodies: per body its mass, its contacts and where it ended.
nlohmann::ordered_json bodiesReport(const sim::Scene& scene, const sim::BodyMotion& motion) {
  nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    std::size_t contacts = 0;
    for (const sim::ContactRecord& c : motion.contacts.records)
      contacts += (c.bodyA == int(b) || c.bodyB == int(b)) ? 1 : 0;
    const Vec3 moved = motion.paths[b].back().translate;
    bodies.push_back({{"name", scene.bodies[b].name},
                      {"static", scene.bodies[b].isStatic},
                      {"mass_kg", motion.contacts.bodies[b].mass},
                      {"contact_records", contacts},
                      {"largest_submerged_share", motion.largestSubmergedShare[b]},
                      {"displacement_m", {moved[0], moved[1], moved[2]}}});
  }
  return {{"substep_s", motion.contacts.substep}, {"contact_log", "contacts.bin"}, {"bodies", bodies}};
}

/// The signal that ended the frames, if any (each written frame is whole); a frame whose writing
/// it ended is dropped from the result, so that the report lists the frames before it.
std::optional<io::Interrupted> stopOf(const FrameWriter& writer, sim::SimulationResult& result) {
  if (writer.unwritten()) {
    const int frame = writer.unwritten()->first;
    std::erase_if(result.frames, [&](const sim::FrameRecord& r) { return r.frame >= frame; });
    return writer.unwritten()->second;
  }
  if (result.interrupted)
    return io::Interrupted(io::interruptionSignal(),
                           "simulate frame " + std::to_string(result.interrupted->frame));
  return std::nullopt;
}

}  // namespace

SimulateOutcome simulateIntoFolder(const SimulateOptions& o) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  // The meshes are read into the record; the solver computes their distances on its own grid.
  sim::Scene scene = sceneAtCellSize(io::readScene(o.scene), o.cell);
  requireMemoryForGrid(scene, o.scene, o.cell, physicalMemoryBytes());
  io::loadSceneMeshes(scene);
  const FrameRange range = parseFrameRange(o.frames, sim::lastSceneFrame(scene));
  const std::filesystem::path out = o.output;
  prepareFrameFolder(out, range, o.ply, o.common.quiet);

  FrameWriter writer(out / "frames", o.ply, range.last, scene.time.fps, o.common.quiet);
  sim::SimulationResult result = simulateScene(scene, o.scene, range, writer);
  writer.finish();
  const std::optional<io::Interrupted> interrupted = stopOf(writer, result);
  const auto w0 = Clock::now();
  SimulateOutcome outcome;
  if (!interrupted) {
    outcome.tracks = io::bubbleTracksFromHistories(result.bubbles, scene);
    io::writeBubbleTracks(out / "bubbles.json", outcome.tracks);
    if (result.bodies) io::writeContactLog(out / "contacts.bin", result.bodies->contacts);
  }
  const double writeSeconds = result.observerSeconds + std::chrono::duration<double>(Clock::now() - w0).count();

  RunReport report("simulate");
  addSimulationResults(report, o, scene, result);
  if (result.bodies) report.resultJson("bodies", bodiesReport(scene, *result.bodies).dump());
  report.stageSeconds("simulation", result.simulationSeconds);
  report.stageSeconds("bubbles", result.bubbleSeconds);
  report.stageSeconds("output", writeSeconds);
  report.result("seconds", std::chrono::duration<double>(Clock::now() - start).count());
  if (interrupted) report.markIncomplete(interrupted->where());
  outcome.report = report.document();
  io::writeTextFile(out / "report.json", jsonFileText(outcome.report));
  if (interrupted)
    throw io::Interrupted(interrupted->signalNumber(), interrupted->where(),
                          (out / "report.json").string() + " marked incomplete");
  return outcome;
}

int runSimulateCommand(const SimulateOptions& o) {
  simulateIntoFolder(o);
  return kExitSuccess;
}

}  // namespace fluidsound::tools
