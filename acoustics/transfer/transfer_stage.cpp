// acoustics/transfer/transfer_stage.cpp — see transfer_stage.h.
#include "acoustics/transfer/transfer_stage.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "acoustics/bubble/minnaert.h"
#include "acoustics/transfer/frame_samples.h"

namespace fluidsound::acoustics {

TransferInputError::TransferInputError(TransferInput input, std::string field, std::string expected,
                                       std::string found)
    : std::invalid_argument(field + ": expected " + expected + ", found " + found),
      input_(input),
      field_(std::move(field)),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

namespace {

/// Signed distance [m] of `x` from `plane` along its normal: > 0 on the air side.
double sideOf(const Vec3& x, const LocalSurface& plane) {
  double d = 0.0;
  for (int a = 0; a < 3; ++a) d += (x[a] - plane.point[a]) * plane.normal[a];
  return d;
}

/// The transfer values of one sample to every listener.
std::vector<double> sampleTransfer(const Vec3& centre, double depth, const LocalSurface& local,
                                   double omega, const TransferSetup& setup) {
  // The horizontal plane at the track's depth: used for a listener that the tilted local plane
  // (a splash sheet, liquid running up a wall) would put under water while it is above the
  // liquid — the flat-surface model cannot turn an air listener into a water one.
  LocalSurface level{centre, setup.up, depth};
  for (int a = 0; a < 3; ++a) level.point[a] += depth * setup.up[a];
  std::vector<double> transfer;
  for (std::size_t l = 0; l < setup.listeners.size(); ++l) {
    const Vec3& x = setup.listeners[l].position;
    const bool tiltedHidesAirListener = sideOf(x, level) > 0.0 && sideOf(x, local) <= 0.0;
    try {
      transfer.push_back(imageSourceTransferAmplitude(
          centre, tiltedHidesAirListener ? level : local, x, omega, setup.liquid, setup.air));
    } catch (const std::invalid_argument& e) {
      throw TransferInputError(TransferInput::Listeners,
                               "listeners[" + std::to_string(l) + "].position",
                               "a listener away from every bubble and its surface point", e.what());
    }
  }
  return transfer;
}

void transferOfFrame(BubbleTrackSet& tracks, int frame, const FrameSamples& samples,
                     const FrameSurfaces& frames, const TransferSetup& setup) {
  const std::unique_ptr<FrameSurface> surface = frames.open(frame);
  for (const auto& [b, s] : samples) {
    BubbleTrack& bubble = tracks.bubbles[b];
    TrackSample& sample = bubble.track[s];
    const Vec3& position = samplePosition(tracks, b, s);
    const LocalSurface local = surface->surfaceAbove(position, sample.depth, setup.up);
    const double pressure = ambientPressureAt(sample.depth, setup.liquid, setup.model);
    const double omega =
        naturalAngularFrequency(bubble.radius, pressure, setup.liquid, setup.model);
    sample.transfer = sampleTransfer(position, sample.depth, local, omega, setup);
  }
}

}  // namespace

TransferResult computeTransfer(BubbleTrackSet tracks, const FrameSurfaces& frames,
                               const TransferSetup& setup, StageObserver& observer) {
  const auto start = std::chrono::steady_clock::now();
  TransferResult result;
  for (BubbleTrack& b : tracks.bubbles) b.rings.clear();  // an earlier run's: this model has none
  const std::vector<std::pair<int, FrameSamples>> work = samplesByFrame(tracks, setup);
  forEachFrameInChunks(work, observer, [&](std::size_t f) {
    transferOfFrame(tracks, work[f].first, work[f].second, frames, setup);
  });
  result.bubbles = tracks.bubbles.size();
  for (const auto& frame : work) result.samples += frame.second.size();
  result.framesRead = work.size();
  result.tracks = std::move(tracks);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace fluidsound::acoustics
