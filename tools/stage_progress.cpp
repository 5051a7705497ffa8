// tools/stage_progress.cpp — see stage_progress.h.
#include "tools/stage_progress.h"

#include <utility>

#include "io/interruption.h"

namespace fluidsound::tools {

StageProgress::StageProgress(std::string stage, std::string unit, bool quiet)
    : stage_(std::move(stage)), unit_(std::move(unit)), quiet_(quiet) {}

void StageProgress::started(double totalUnits) {
  if (totalUnits > 0)
    display_.emplace(stage_, totalUnits, unit_, quiet_);
  else
    display_.emplace(stage_, 1.0, "", quiet_);
}

void StageProgress::progress(double fraction) {
  if (display_) display_->update(fraction);
}

bool StageProgress::wasInterrupted() { return io::interruptionRequested(); }

void StageProgress::finish() {
  if (display_) display_->finish();
}

}  // namespace fluidsound::tools
