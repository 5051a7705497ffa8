// tools/transfer_command.cpp — see transfer_command.h.
#include "tools/transfer_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "acoustics/image_source_transfer.h"
#include "acoustics/minnaert.h"
#include "acoustics/oscillator_model.h"
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
      "transfer", "fill the transfer values of OUTDIR/bubbles.json from frames/*.vdb (image-source model)");
  c->add_option("scene", o.scene, "scene file (fluidsound.scene/1): listeners, frame rate, gravity")->required();
  c->add_option("-o,--output", o.output, "the folder `fluidsound simulate` wrote")->required();
  addCommonOptions(*c, o.common);
  return c;
}

namespace {
/// Frames evaluated in parallel between two progress updates.
constexpr std::size_t kFramesPerProgressStep = 8;

std::string frameFile(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frames/%04d.vdb", frame);
  return name;
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
    throw io::InputError(tracksPath.string(), "listeners", "the scene's listeners (" + std::to_string(names.size()) + ")",
                         std::to_string(tracks.listeners.size()) + " other names: simulate the scene again");
  io::requireWritableFolder(tracksPath);
  io::requireWritableFolder(out / "transfer.report.json");

  // Up: against gravity (the fallback normal of a surface seen from below).
  const sim::Vec3& g = scene.gravity;
  const double gNorm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  const acoustics::Vec3 up = gNorm > 0.0 ? acoustics::Vec3{-g[0] / gNorm, -g[1] / gNorm, -g[2] / gNorm}
                                         : acoustics::Vec3{0.0, 1.0, 0.0};
  // The samples of every frame, so that each frame file is read once.
  const int lastFrame = static_cast<int>(std::lround(scene.time.duration * scene.time.fps));
  std::map<int, std::vector<std::pair<std::size_t, std::size_t>>> samplesOfFrame;
  std::size_t sampleCount = 0;
  for (std::size_t b = 0; b < tracks.bubbles.size(); ++b)
    for (std::size_t s = 0; s < tracks.bubbles[b].track.size(); ++s, ++sampleCount) {
      const int frame = std::clamp(static_cast<int>(std::lround(tracks.bubbles[b].track[s].time * scene.time.fps)), 0,
                                   lastFrame);
      samplesOfFrame[frame].emplace_back(b, s);
    }
  const acoustics::LiquidProperties liquid;
  const acoustics::AirProperties air;
  const acoustics::OscillatorModel model;
  // Frames are independent (each sample belongs to one frame and is written by it alone), so they
  // are read and evaluated in parallel, a chunk at a time for the progress display. An error is
  // kept per frame and the first in frame order is thrown, as a serial loop would.
  const std::vector<std::pair<int, std::vector<std::pair<std::size_t, std::size_t>>>> frames(samplesOfFrame.begin(),
                                                                                              samplesOfFrame.end());
  const auto transferOfFrame = [&](int frame, const std::vector<std::pair<std::size_t, std::size_t>>& samples) {
    const io::FrameSurface surface(out / frameFile(frame));
    for (const auto& [b, s] : samples) {
      acoustics::BubbleTrack& bubble = tracks.bubbles[b];
      acoustics::TrackSample& sample = bubble.track[s];
      if (!sample.position)
        throw io::InputError(tracksPath.string(), "bubbles[" + std::to_string(b) + "].track[" + std::to_string(s) + "]",
                             "a position (written by fluidsound simulate)", "none");
      const acoustics::LocalSurface local = surface.surfaceAbove(*sample.position, sample.depth, up);
      // The horizontal plane at the track's depth: used for a listener that the tilted local plane
      // (a splash sheet, liquid running up a wall) would put under water while it is above the
      // liquid — the flat-surface model cannot turn an air listener into a water one.
      acoustics::LocalSurface level{*sample.position, up, sample.depth};
      for (int a = 0; a < 3; ++a) level.point[a] += sample.depth * up[a];
      const double omega = acoustics::naturalAngularFrequency(bubble.radius, liquid.ambientPressure, liquid, model);
      sample.transfer.clear();
      for (std::size_t l = 0; l < scene.listeners.size(); ++l) {
        try {
          const sim::Vec3& x = scene.listeners[l].position;
          const auto side = [&x](const acoustics::LocalSurface& plane) {
            double d = 0.0;
            for (int a = 0; a < 3; ++a) d += (x[a] - plane.point[a]) * plane.normal[a];
            return d;
          };
          const bool tiltedHidesAirListener = side(level) > 0.0 && side(local) <= 0.0;
          sample.transfer.push_back(acoustics::imageSourceTransferAmplitude(
              *sample.position, tiltedHidesAirListener ? level : local, x, omega, liquid, air));
        } catch (const std::invalid_argument& e) {
          throw io::InputError(scene.file.string(), "listeners[" + std::to_string(l) + "].position",
                               "a listener away from every bubble and its surface point", e.what());
        }
      }
    }
  };
  ProgressDisplay progress("transfer", static_cast<int>(frames.size()), "frames", o.common.quiet);
  std::vector<std::exception_ptr> errors(frames.size());
  for (std::size_t first = 0; first < frames.size(); first += kFramesPerProgressStep) {
    const std::size_t last = std::min(frames.size(), first + kFramesPerProgressStep);
    io::throwIfInterrupted("transfer frame " + std::to_string(frames[first].first));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 1), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t f = r.begin(); f < r.end(); ++f) {
        try {
          transferOfFrame(frames[f].first, frames[f].second);
        } catch (...) {
          errors[f] = std::current_exception();
        }
      }
    });
    for (std::size_t f = first; f < last; ++f)
      if (errors[f]) std::rethrow_exception(errors[f]);
    progress.update(static_cast<double>(last) / frames.size());
  }
  progress.finish();
  io::writeBubbleTracks(tracksPath, tracks);

  RunReport report("transfer");
  report.setting("scene", o.scene);
  report.setting("output", o.output);
  report.setting("model", "image source, locally flat surface (docs/transfer.md)");
  report.result("bubbles", static_cast<double>(tracks.bubbles.size()));
  report.result("samples", static_cast<double>(sampleCount));
  report.result("frames_read", static_cast<double>(samplesOfFrame.size()));
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  report.stageSeconds("transfer", seconds);
  report.result("seconds", seconds);
  report.write(out / "transfer.report.json");
  return kExitSuccess;
}

}  // namespace fluidsound::tools
