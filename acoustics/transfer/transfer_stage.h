// acoustics/transfer/transfer_stage.h — the transfer stage as one library function: every track sample's
// transfer value to every listener, with the image-source model (acoustics/transfer/image_source_transfer.h)
// under the local surface of the sample's frame. Frames come through an interface, so the stage
// reads no files (io/frame_surface.h implements it over frames/NNNN.vdb). docs/transfer.md.
#pragma once

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/transfer/image_source_transfer.h"
#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/bubble/oscillator_model.h"
#include "sim/core/stage_observer.h"

namespace fluidsound::acoustics {

/// The liquid surface of one frame, queried for the plane above a bubble.
class FrameSurface {
 public:
  virtual ~FrameSurface() = default;
  /// The free surface above the bubble at `centre` [m], `depth` [m] > 0 below it along the unit
  /// vector `up` (against gravity), as a local plane.
  virtual LocalSurface surfaceAbove(const Vec3& centre, double depth, const Vec3& up) const = 0;
};

/// The frames of a simulation. open() is called once per frame that has samples, from several
/// threads at once; it may throw (a missing or damaged frame), which ends the stage with that
/// error.
class FrameSurfaces {
 public:
  virtual ~FrameSurfaces() = default;
  virtual std::unique_ptr<FrameSurface> open(int frame) const = 0;
};

/// One listener of the scene.
struct TransferListener {
  std::string name;
  Vec3 position{};  ///< [m], world space
};

/// Everything the stage needs besides the tracks and the frames.
struct TransferSetup {
  std::vector<TransferListener> listeners;
  Vec3 up{0.0, 1.0, 0.0};  ///< unit vector against gravity [-]
  double fps = 30.0;       ///< frame rate [1/s]: sample at time t belongs to frame round(t·fps)
  int lastFrame = 0;       ///< frames are clamped to 0 … lastFrame
  LiquidProperties liquid;
  AirProperties air;
  OscillatorModel model;  ///< gives ω of each bubble, the same model synthesis uses
};

/// What the geometric model's solves did (acoustics/transfer/geometric_transfer.h).
struct GeometricTransferStats {
  std::size_t reciprocalFrames = 0;  ///< frames solved once per band and listener
  std::size_t adjointFrames = 0;     ///< frames solved once per sample
  std::size_t widenedFrames = 0;     ///< reciprocal frames whose bands hit the band limit
  std::size_t modeLimitedFrames = 0; ///< frames with too many modes below the cut: adjoint route
  std::size_t bands = 0;             ///< bands over all reciprocal frames
  std::size_t modes = 0;             ///< water modes taken out, over all frames that found theirs
  std::size_t factorisations = 0;    ///< sparse factorisations (bands, samples, mode shifts)
  std::size_t solves = 0;            ///< back-substitutions (Lanczos steps included)
  std::size_t maxUnknowns = 0;       ///< liquid cells of the largest frame
  double maxFrequency = 0.0;         ///< highest sample frequency [Hz]
  std::size_t samplesOutsideLiquid = 0;  ///< samples with no liquid cell around them: level plane
  std::size_t samplesAboveLimit = 0;     ///< samples above the frequency limit: level plane
  std::size_t airSolves = 0;   ///< wave solves of the air side (per listener and solve time)
  std::size_t airSamples = 0;  ///< samples whose p_L came from them (adjoint route)
  double airSeconds = 0.0;     ///< wall-clock time of the air side's wave solves [s]
  std::size_t rings = 0;       ///< bubbles given an air column's ring (resonator_ring.h)
  std::size_t airBytes = 0;    ///< memory their fields hold until the stage ends [bytes]
  double solveSeconds = 0.0;         ///< summed over threads: assembly, factorisation, solves
  bool operator==(const GeometricTransferStats&) const = default;
};

/// The filled tracks and what the stage did.
struct TransferResult {
  BubbleTrackSet tracks;
  std::size_t bubbles = 0;
  std::size_t samples = 0;
  std::size_t framesRead = 0;
  double seconds = 0.0;  ///< wall-clock time of computeTransfer
  GeometricTransferStats geometric;  ///< zero for the image-source model
};

/// Which input a TransferInputError is about.
enum class TransferInput {
  Tracks,     ///< the bubble tracks (field e.g. "bubbles[3].track[2]")
  Listeners,  ///< the scene's listeners (field e.g. "listeners[1].position")
  Options,    ///< the scene's "transfer" block (field e.g. "transfer.max_bands")
};

/// Bad input found by computeTransfer: the caller names the file (io::InputError). what() is
/// "FIELD: expected EXPECTED, found FOUND".
class TransferInputError : public std::invalid_argument {
 public:
  TransferInputError(TransferInput input, std::string field, std::string expected,
                     std::string found);
  TransferInput input() const { return input_; }
  const std::string& field() const { return field_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }

 private:
  TransferInput input_;
  std::string field_, expected_, found_;
};

/// A frame whose water-side solve failed or gave a non-finite value. what() names the frame.
class TransferSolveError : public std::runtime_error {
 public:
  TransferSolveError(int frame, const std::string& reason)
      : std::runtime_error("transfer frame " + std::to_string(frame) + ": " + reason),
        frame_(frame) {}
  int frame() const { return frame_; }

 private:
  int frame_;
};

/// @brief Fills `transfer` (one value per listener) in every track sample. Per sample: the plane
///        frames.open(frame).surfaceAbove(position, depth, up), except where that tilted plane
///        would put a listener that is above the level plane at the track's depth (normal `up`)
///        under water — then the level plane (the flat-surface model cannot turn an air listener
///        into a water one); ω is the bubble's natural frequency under setup.model at the sample's
///        depth. Frames are evaluated in parallel a chunk at a time: observer.started(frames with
///        samples) first, then observer.wasInterrupted() before and observer.progress() after each
///        chunk; the result does not depend on the thread count.
/// @throws TransferInputError for a sample with no position, or a listener at a bubble or its
///         surface point; StageInterrupted("transfer frame F") when the observer asks to stop before
///         frame F's chunk; else what frames.open() threw. Of several
///         failing frames, the first in frame order's error is thrown.
TransferResult computeTransfer(BubbleTrackSet tracks, const FrameSurfaces& frames,
                               const TransferSetup& setup, StageObserver& observer);

/// Frames evaluated in parallel between two observer calls.
inline constexpr std::size_t kTransferFramesPerChunk = 8;

}  // namespace fluidsound::acoustics
