// tools/transfer_command.cpp — see transfer_command.h.
#include "tools/transfer_command.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "acoustics/transfer/level_set_surface.h"
#include "acoustics/transfer/transfer_stage.h"
#include "io/bubble_track_file.h"
#include "io/frame_surface.h"
#include "io/input_error.h"
#include "io/interruption.h"
#include "io/scene_file.h"
#include "io/text_file.h"
#include "tools/run_report.h"
#include "tools/stage_progress.h"
#include "tools/transfer_report.h"

namespace fluidsound::tools {

CLI::App* addTransferCommand(CLI::App& app, TransferOptions& o) {
  CLI::App* c = app.add_subcommand(
      "transfer",
      "fill the transfer values of OUTDIR/bubbles.json from frames/*.vdb (image-source model)");
  c->add_option("scene", o.scene, "scene file (fluidsound.scene/1): listeners, frame rate, gravity")
      ->required();
  c->add_option("-o,--output", o.output, "the folder `fluidsound simulate` wrote")->required();
  addOscillatorModelOptions(*c, o.model);
  addCommonOptions(*c, o.common);
  return c;
}

namespace {

/// The scene's listeners, up (against gravity, else +y), frame rate and last frame, and the model.
acoustics::TransferSetup transferSetup(const sim::Scene& scene,
                                       const acoustics::OscillatorModel& model) {
  acoustics::TransferSetup setup;
  for (const sim::Listener& l : scene.listeners) setup.listeners.push_back({l.name, l.position});
  const Vec3& g = scene.gravity;
  const double gNorm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if (gNorm > 0.0) setup.up = {-g[0] / gNorm, -g[1] / gNorm, -g[2] / gNorm};
  setup.fps = scene.time.fps;
  setup.lastFrame = static_cast<int>(std::lround(scene.time.duration * scene.time.fps));
  setup.model = model;
  return setup;
}

/// OUTDIR/bubbles.json as simulate wrote it (transfer values, if any, are recomputed), for the
/// scene's listeners.
acoustics::BubbleTrackSet readSimulatedTracks(const std::filesystem::path& tracksPath,
                                              const sim::Scene& scene) {
  acoustics::BubbleTrackSet tracks = io::readBubbleTracks(tracksPath, io::TransferValues::Optional);
  std::vector<std::string> names;
  for (const sim::Listener& l : scene.listeners) names.push_back(l.name);
  if (tracks.listeners != names)
    throw io::InputError(
        tracksPath.string(), "listeners",
        "the scene's listeners (" + std::to_string(names.size()) + ")",
        std::to_string(tracks.listeners.size()) + " other names: simulate the scene again");
  return tracks;
}

}  // namespace

acoustics::BubbleTrackSet transferInFolder(const TransferOptions& o, const sim::Scene& scene,
                                           std::optional<acoustics::BubbleTrackSet> tracks) {
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path out = o.output, tracksPath = out / "bubbles.json";
  if (!tracks) tracks = readSimulatedTracks(tracksPath, scene);
  io::requireWritableFolder(tracksPath);
  io::requireWritableFolder(out / "transfer.report.json");

  StageProgress observer("transfer", "frames", o.common.quiet);
  const io::FrameFolderLevelSets levelSets(out);
  const acoustics::LevelSetFrameSurfaces frames(levelSets);
  acoustics::TransferResult result;
  try {
    result = acoustics::computeTransfer(std::move(*tracks), frames,
                                        transferSetup(scene, o.model), observer);
  } catch (const acoustics::TransferInputError& e) {
    const bool aboutTracks = e.input() == acoustics::TransferInput::Tracks;
    throw io::InputError(aboutTracks ? tracksPath.string() : scene.file.string(), e.field(),
                         e.expected(), e.found());
  } catch (const StageInterrupted& e) {
    throw io::Interrupted(io::interruptionSignal(), e.what());
  }
  observer.finish();
  io::writeBubbleTracks(tracksPath, result.tracks);

  RunReport report("transfer");
  addTransferResults(report, o, result);
  report.result("seconds",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  report.write(out / "transfer.report.json");
  return std::move(result.tracks);
}

int runTransferCommand(const TransferOptions& o) {
  transferInFolder(o, io::readScene(o.scene), std::nullopt);
  return kExitSuccess;
}

}  // namespace fluidsound::tools
