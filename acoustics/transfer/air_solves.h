// acoustics/transfer/air_solves.h — the wave solves of the air side (wave_air_field.h) that a run
// of the geometric transfer reads: one per listener every `interval` seconds at the frames that
// have samples, each from the frame nearest its time. docs/transfer.md, "The air side".
#pragma once

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "acoustics/transfer/frame_samples.h"
#include "acoustics/transfer/transfer_stage.h"
#include "acoustics/transfer/water_grid.h"
#include "acoustics/transfer/wave_air_field.h"

namespace fluidsound::acoustics {

/// The wave solves of the air side a frame reads, one per listener; empty: the rigid-surface
/// field alone.
using FrameAirFields = std::vector<const WaveAirField*>;

/// The air side's wave solves of a run: one per listener every `interval` seconds at the frames
/// that have samples, each from the frame nearest its time; a frame reads the solve nearest it.
/// All are solved up front, in parallel, so the values do not depend on the thread count.
class AirSolves {
 public:
  AirSolves() = default;
  /// Solves every field `work`'s frames need, in parallel.
  AirSolves(const std::vector<std::pair<int, FrameSamples>>& work, const FrameWaterGrids& grids,
            const TransferSetup& setup, const WaveAirOptions& options);
  /// The fields frame `frame` reads (empty without the wave air side).
  const FrameAirFields& forFrame(int frame) const;
  /// Solves held (listeners × solve times).
  std::size_t count() const { return fields_.size(); }
  /// Wall-clock time the solves took [s].
  double seconds() const { return seconds_; }
  /// Memory the solved fields hold [bytes].
  std::size_t bytes() const;

 private:
  int indexOf(int frame) const;
  double fps_ = 30.0, interval_ = 0.0, seconds_ = 0.0;
  std::vector<std::unique_ptr<WaveAirField>> fields_;
  std::map<int, FrameAirFields> byIndex_;
  FrameAirFields none_;  ///< what a frame without a solve reads
};

}  // namespace fluidsound::acoustics
