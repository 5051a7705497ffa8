// acoustics/stage_observer.h — how a long stage reports progress and learns that it should stop,
// without printing or knowing about signals (OpenVDB's util::NullInterrupter pattern): the stage
// calls started() once it knows how much work there is, progress() after each chunk of work and
// checkpoint() before the next; the caller's
// observer draws a progress line, or throws from checkpoint() to end the stage cleanly.
#pragma once

#include <string>

namespace fluidsound::acoustics {

/// Does nothing by default: a stage run with a plain StageObserver is silent and never stopped.
class StageObserver {
 public:
  virtual ~StageObserver() = default;
  /// @param totalUnits  the stage's work in its own units (transfer: frames), before the first
  /// chunk
  virtual void started(double totalUnits) { (void)totalUnits; }
  /// @param fraction  0 … 1 of the stage's work done
  virtual void progress(double fraction) { (void)fraction; }
  /// @brief Called between chunks of work, where stopping leaves nothing half-done; throws to stop.
  /// @param where  the stage and step about to start, e.g. "transfer frame 12"
  virtual void checkpoint(const std::string& where) { (void)where; }
};

}  // namespace fluidsound::acoustics
