// tools/transfer_command.cpp — see transfer_command.h.
#include "tools/transfer_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "acoustics/transfer/geometric_transfer.h"
#include "acoustics/transfer/level_set_surface.h"
#include "acoustics/transfer/transfer_stage.h"
#include "io/bubble_track_file.h"
#include "io/frame_surface.h"
#include "io/input_error.h"
#include "io/interruption.h"
#include "io/scene_file.h"
#include "io/scene_meshes.h"
#include "io/text_file.h"
#include "tools/frame_water_grids.h"
#include "tools/run_report.h"
#include "tools/stage_progress.h"
#include "tools/transfer_report.h"

namespace fluidsound::tools {

CLI::App* addTransferCommand(CLI::App& app, TransferOptions& o) {
  CLI::App* c = app.add_subcommand(
      "transfer",
      "fill the transfer values of OUTDIR/bubbles.json from frames/*.vdb and the scene's solids");
  c->add_option("scene", o.scene,
                "scene file (fluidsound.scene/1): listeners, solids, frame rate, gravity")
      ->required();
  c->add_option("-o,--output", o.output, "the folder `fluidsound simulate` wrote")->required();
  addTransferModelOption(*c, o.transfer);
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

/// The frame of the first track sample (frame order), by the stage's rule: round(t·fps), clamped
/// to 0 … lastFrame; none without samples.
std::optional<int> firstSampleFrame(const acoustics::BubbleTrackSet& tracks,
                                    const acoustics::TransferSetup& setup) {
  std::optional<int> first;
  for (const acoustics::BubbleTrack& bubble : tracks.bubbles)
    for (const acoustics::TrackSample& sample : bubble.track) {
      const double frame = std::clamp(std::round(sample.time * setup.fps), 0.0,
                                      static_cast<double>(setup.lastFrame));
      first = std::min(first.value_or(setup.lastFrame), static_cast<int>(frame));
    }
  return first;
}

/// The scene with its mesh solids read, if they are not (the geometric model's solids).
sim::Scene withSolidMeshes(const sim::Scene& scene) {
  sim::Scene loaded = scene;
  const bool missing = std::any_of(scene.solids.begin(), scene.solids.end(), [](const sim::Solid& s) {
    const auto* mesh = std::get_if<sim::MeshFile>(&s.shape);
    return mesh != nullptr && !mesh->surface;
  });
  if (missing) io::loadSceneMeshes(loaded);
  return loaded;
}

/// The chosen model over OUTDIR's frames: the image-source model under each frame's level set,
/// or the geometric model on each frame's water grid at the simulation's cell size.
acoustics::TransferResult runTransferModel(const TransferChoice& choice,
                                           acoustics::BubbleTrackSet tracks,
                                           const sim::Scene& scene,
                                           const std::filesystem::path& out,
                                           const acoustics::OscillatorModel& model,
                                           StageObserver& observer) {
  const acoustics::TransferSetup setup = transferSetup(scene, model);
  if (choice.model == sim::TransferModel::Image) {
    const io::FrameFolderLevelSets levelSets(out);
    const acoustics::LevelSetFrameSurfaces frames(levelSets);
    return acoustics::computeTransfer(std::move(tracks), frames, setup, observer);
  }
  const sim::Scene solids = withSolidMeshes(scene);
  const std::optional<int> first = firstSampleFrame(tracks, setup);
  const double cell = first ? simulatedCellSize(solids, out, *first) : scene.domain.cell;
  const FrameFolderWaterGrids frames(solids, out, cell);
  return acoustics::computeGeometricTransfer(std::move(tracks), frames, setup, choice.geometric,
                                             observer);
}

}  // namespace

acoustics::BubbleTrackSet transferInFolder(const TransferOptions& o, const sim::Scene& scene,
                                           std::optional<acoustics::BubbleTrackSet> tracks) {
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path out = o.output, tracksPath = out / "bubbles.json";
  if (!tracks) tracks = readSimulatedTracks(tracksPath, scene);
  io::requireWritableFolder(tracksPath);
  io::requireWritableFolder(out / "transfer.report.json");

  const TransferChoice choice = transferChoice(scene, o.transfer);
  StageProgress observer("transfer", "frames", o.common.quiet);
  acoustics::TransferResult result;
  try {
    result = runTransferModel(choice, std::move(*tracks), scene, out, o.model, observer);
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
  addTransferResults(report, o, choice, result);
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
