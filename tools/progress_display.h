// tools/progress_display.h — progress of a long stage on the terminal: stage, fraction, rate,
// ETA. On a terminal one line is redrawn in place; in a log, a plain line every few seconds.
// Shown only once the stage has run for a second, so quick runs stay quiet. Log lines printed
// through log() while the progress line is up clear it first and redraw it after, so the two
// never run into each other.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace fluidsound::tools {

class ProgressDisplay {
 public:
  /// @param stage      what is running, e.g. "synth"
  /// @param totalUnits amount of work in `unit`s, e.g. seconds of audio
  /// @param unit       name of the unit for the rate, e.g. "s audio"
  /// @param quiet      show nothing (log() lines too)
  /// Draws on stderr, redrawing in place if stderr is a terminal.
  ProgressDisplay(std::string stage, double totalUnits, std::string unit, bool quiet);
  /// Where a display draws (for tests and other streams than stderr).
  struct Target {
    std::FILE* stream = stderr;
    bool terminal = false;          ///< redraw one line in place
    double showAfterSeconds = 1.0;  ///< nothing is shown before [s]
  };
  /// The same on `target`.
  ProgressDisplay(std::string stage, double totalUnits, std::string unit, bool quiet,
                  const Target& target);
  ~ProgressDisplay();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

  /// @param fraction  0 … 1 of the work done
  void update(double fraction);

  /// Prints one log line (a newline is added): on a terminal with the progress line up, the
  /// progress line is cleared first and drawn again below the log line.
  void log(const std::string& line);

  /// Ends the line on a terminal (if anything was shown).
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::string stage_, unit_;
  double totalUnits_;
  double showAfterSeconds_;
  bool quiet_;
  std::FILE* stream_;
  bool terminal_;
  bool shown_ = false;  ///< the progress line is on the terminal's last line now
  std::string drawn_;   ///< its text, to draw again after a log line
  Clock::time_point start_, lastLine_;
};

/// Formats a duration in seconds as "12 s", "3 min 04 s" or "1 h 02 min".
std::string formatDuration(double seconds);

}  // namespace fluidsound::tools
