// tools/progress_display.cpp — terminal progress (see progress_display.h).
#include "tools/progress_display.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fluidsound::tools {
namespace {
constexpr double kShowAfterSeconds = 1.0;      // quick stages print nothing
constexpr double kLogIntervalSeconds = 5.0;    // plain lines when stderr is not a terminal
/// Carriage return, then erase to the end of the line (ECMA-48 EL, "CSI K").
constexpr const char* kClearLine = "\r\x1b[K";
}  // namespace

std::string formatDuration(double seconds) {
  char text[48];
  const long s = std::lround(std::max(seconds, 0.0));
  if (s < 60) std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600) std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  return text;
}

ProgressDisplay::ProgressDisplay(std::string stage, double totalUnits, std::string unit, bool quiet)
    : ProgressDisplay(std::move(stage), totalUnits, std::move(unit), quiet,
                      {stderr, isatty(STDERR_FILENO) != 0, kShowAfterSeconds}) {}

ProgressDisplay::ProgressDisplay(std::string stage, double totalUnits, std::string unit, bool quiet,
                                 const Target& target)
    : stage_(std::move(stage)),
      unit_(std::move(unit)),
      totalUnits_(totalUnits),
      showAfterSeconds_(target.showAfterSeconds),
      quiet_(quiet),
      stream_(target.stream),
      terminal_(target.terminal),
      start_(Clock::now()),
      lastLine_(start_) {}

ProgressDisplay::~ProgressDisplay() { finish(); }

void ProgressDisplay::update(double fraction) {
  if (quiet_) return;
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < showAfterSeconds_) return;
  if (!terminal_ && std::chrono::duration<double>(now - lastLine_).count() < kLogIntervalSeconds &&
      fraction < 1.0)
    return;
  lastLine_ = now;
  const double rate = fraction * totalUnits_ / elapsed;
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  char text[256];
  std::snprintf(text, sizeof text, "%s %5.1f%%  %.3g %s/s  elapsed %s  ETA %s", stage_.c_str(),
                100.0 * fraction, rate, unit_.c_str(), formatDuration(elapsed).c_str(),
                formatDuration(eta).c_str());
  drawn_ = text;
  if (terminal_) {
    std::fprintf(stream_, "%s%s", kClearLine, drawn_.c_str());
    shown_ = true;
  } else {
    std::fprintf(stream_, "%s\n", drawn_.c_str());
  }
  std::fflush(stream_);
}

void ProgressDisplay::log(const std::string& line) {
  if (quiet_) return;
  if (shown_) {
    std::fprintf(stream_, "%s%s\n%s", kClearLine, line.c_str(), drawn_.c_str());
  } else {
    std::fprintf(stream_, "%s\n", line.c_str());
  }
  std::fflush(stream_);
}

void ProgressDisplay::finish() {
  if (shown_) std::fputc('\n', stream_);
  shown_ = false;
}

}  // namespace fluidsound::tools
