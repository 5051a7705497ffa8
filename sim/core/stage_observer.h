// sim/core/stage_observer.h — how a long stage reports progress and learns that it should stop,
// without printing or knowing about signals (OpenVDB's util::NullInterrupter pattern): the stage
// calls started() once it knows how much work there is, progress() after each chunk of work and
// asks wasInterrupted() before the next, where stopping leaves nothing half-done. The caller's
// observer draws a progress line and answers from its signal handler. Every stage function
// (sim::simulate, acoustics::computeTransfer, acoustics::synthesize) takes one.
#pragma once

#include <stdexcept>
#include <string>

namespace fluidsound {

/// Does nothing by default: a stage run with a plain StageObserver is silent and never stopped.
class StageObserver {
 public:
  virtual ~StageObserver() = default;
  /// @param totalUnits  the stage's work in its own units (frames, samples), before the first chunk
  virtual void started(double totalUnits) { (void)totalUnits; }
  /// @param fraction  0 … 1 of the stage's work done
  virtual void progress(double fraction) { (void)fraction; }
  /// @return true to stop the stage at this point between chunks of work
  virtual bool wasInterrupted() { return false; }
};

/// @brief Thrown by a stage that stops because its observer's wasInterrupted() said so, where the
///        stage has no partial result to return. what() is `where`, e.g. "transfer frame 12".
class StageInterrupted : public std::runtime_error {
 public:
  explicit StageInterrupted(const std::string& where) : std::runtime_error(where) {}
};

}  // namespace fluidsound
