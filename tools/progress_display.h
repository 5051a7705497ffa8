// tools/progress_display.h — progress of a long stage on the terminal: stage, fraction, rate,
// ETA. On a terminal one line is redrawn in place; in a log, a plain line every few seconds.
// Shown only once the stage has run for a second, so quick runs stay quiet.
#pragma once

#include <chrono>
#include <string>

namespace fluidsound::tools {

class ProgressDisplay {
 public:
  /// @param stage      what is running, e.g. "synth"
  /// @param totalUnits amount of work in `unit`s, e.g. seconds of audio
  /// @param unit       name of the unit for the rate, e.g. "s audio"
  /// @param quiet      show nothing
  ProgressDisplay(std::string stage, double totalUnits, std::string unit, bool quiet);
  ~ProgressDisplay();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

  /// @param fraction  0 … 1 of the work done
  void update(double fraction);

  /// Ends the line on a terminal (if anything was shown).
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::string stage_, unit_;
  double totalUnits_;
  bool quiet_, terminal_;
  bool shown_ = false;
  Clock::time_point start_, lastLine_;
};

/// Formats a duration in seconds as "12 s", "3 min 04 s" or "1 h 02 min".
std::string formatDuration(double seconds);

}  // namespace fluidsound::tools
