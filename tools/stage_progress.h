// tools/stage_progress.h — the StageObserver (sim/core/stage_observer.h) of the transfer and synth
// commands: a progress line on the terminal once the stage says how much work it has, and a stop
// when a signal came (io/interruption.h).
#pragma once

#include <optional>
#include <string>

#include "sim/core/stage_observer.h"
#include "tools/progress_display.h"

namespace fluidsound::tools {

class StageProgress : public StageObserver {
 public:
  /// @param stage  the name shown, e.g. "transfer"
  /// @param unit   the unit of the stage's total, e.g. "frames"; a total of 0 (not known ahead)
  ///               is shown as a bare fraction
  StageProgress(std::string stage, std::string unit, bool quiet);
  void started(double totalUnits) override;
  void progress(double fraction) override;
  bool wasInterrupted() override;
  /// Ends the progress line (if one was drawn).
  void finish();

 private:
  std::string stage_, unit_;
  bool quiet_;
  std::optional<ProgressDisplay> display_;
};

}  // namespace fluidsound::tools
