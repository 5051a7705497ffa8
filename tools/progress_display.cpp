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
    : stage_(std::move(stage)), unit_(std::move(unit)), totalUnits_(totalUnits), quiet_(quiet),
      terminal_(isatty(STDERR_FILENO) != 0), start_(Clock::now()), lastLine_(start_) {}

ProgressDisplay::~ProgressDisplay() { finish(); }

void ProgressDisplay::update(double fraction) {
  if (quiet_) return;
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < kShowAfterSeconds) return;
  if (!terminal_ && std::chrono::duration<double>(now - lastLine_).count() < kLogIntervalSeconds &&
      fraction < 1.0)
    return;
  lastLine_ = now;
  const double rate = fraction * totalUnits_ / elapsed;
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "%s%s %5.1f%%  %.3g %s/s  elapsed %s  ETA %s%s", terminal_ ? "\r" : "",
               stage_.c_str(), 100.0 * fraction, rate, unit_.c_str(), formatDuration(elapsed).c_str(),
               formatDuration(eta).c_str(), terminal_ ? "\x1b[K" : "\n");
  std::fflush(stderr);
  shown_ = true;
}

void ProgressDisplay::finish() {
  if (shown_ && terminal_) std::fputc('\n', stderr);
  shown_ = false;
}

}  // namespace fluidsound::tools
