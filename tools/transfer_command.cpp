// tools/transfer_command.cpp — see transfer_command.h.
#include "tools/transfer_command.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "acoustics/transfer/transfer_stage.h"
#include "io/bubble_track_file.h"
#include "io/frame_surface.h"
#include "io/input_error.h"
#include "io/interruption.h"
#include "io/scene_file.h"
#include "io/text_file.h"
#include "tools/progress_display.h"
#include "tools/run_report.h"

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

/// The transfer stage's progress on the terminal; a signal stops it between chunks of frames.
class TransferObserver : public StageObserver {
 public:
  explicit TransferObserver(bool quiet) : quiet_(quiet) {}
  void started(double frames) override { display_.emplace("transfer", frames, "frames", quiet_); }
  void progress(double fraction) override { display_->update(fraction); }
  bool wasInterrupted() override { return io::interruptionRequested(); }
  void finish() {
    if (display_) display_->finish();
  }

 private:
  bool quiet_;
  std::optional<ProgressDisplay> display_;
};

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

}  // namespace

int runTransferCommand(const TransferOptions& o) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const sim::Scene scene = io::readScene(o.scene);
  const std::filesystem::path out = o.output, tracksPath = out / "bubbles.json";
  acoustics::BubbleTrackSet tracks = io::readBubbleTracks(tracksPath, io::TransferValues::Optional);
  std::vector<std::string> names;
  for (const sim::Listener& l : scene.listeners) names.push_back(l.name);
  if (tracks.listeners != names)
    throw io::InputError(
        tracksPath.string(), "listeners",
        "the scene's listeners (" + std::to_string(names.size()) + ")",
        std::to_string(tracks.listeners.size()) + " other names: simulate the scene again");
  io::requireWritableFolder(tracksPath);
  io::requireWritableFolder(out / "transfer.report.json");

  const acoustics::TransferSetup setup = transferSetup(scene, o.model);
  TransferObserver observer(o.common.quiet);
  acoustics::TransferResult result;
  try {
    result = acoustics::computeTransfer(std::move(tracks), io::FrameFolderSurfaces(out), setup,
                                        observer);
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
  report.setting("scene", o.scene);
  report.setting("output", o.output);
  report.setting("model", "image source, locally flat surface (docs/transfer.md)");
  report.setOscillatorModel(o.model);
  report.result("bubbles", static_cast<double>(result.bubbles));
  report.result("samples", static_cast<double>(result.samples));
  report.result("frames_read", static_cast<double>(result.framesRead));
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  report.stageSeconds("transfer", result.seconds);
  report.result("seconds", seconds);
  report.write(out / "transfer.report.json");
  return kExitSuccess;
}

}  // namespace fluidsound::tools
