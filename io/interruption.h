// io/interruption.h — SIGINT and SIGTERM end a command cleanly: the handler only records the
// signal; long loops ask interruptionRequested() and throw Interrupted, whose unwinding removes
// every temporary file (AtomicFile's destructor). A second signal removes the registered
// temporaries at once (unlink, async-signal-safe) and ends the process (docs/cli.md, "Signals").
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace fluidsound::io {

/// @brief Thrown where a long loop noticed a signal. what() is the one-line message, e.g.
///        `interrupted (SIGINT) at simulate frame 12; out/report.json marked incomplete`.
class Interrupted : public std::runtime_error {
 public:
  /// @param where      the stage and step, e.g. "simulate frame 12"
  /// @param aftermath  what the command left for it, e.g. "out/report.json marked incomplete"
  Interrupted(int signalNumber, const std::string& where, const std::string& aftermath = {});
  int signalNumber() const { return signal_; }
  const std::string& where() const { return where_; }
  const std::string& aftermath() const { return aftermath_; }
  /// 128 + the signal's number: 130 for SIGINT, 143 for SIGTERM (the shell's convention).
  int exitCode() const { return 128 + signal_; }

 private:
  int signal_;
  std::string where_, aftermath_;
};

/// @brief Installs the handlers of SIGINT and SIGTERM, and ignores SIGPIPE (a closed pipe is then
///        a write error, EPIPE, reported in one line). Called once, by main().
void installInterruptionHandlers();

/// @return the first signal received (SIGINT or SIGTERM), or 0 if none
int interruptionSignal();

/// @return true once SIGINT or SIGTERM was received
inline bool interruptionRequested() { return interruptionSignal() != 0; }

/// @brief Throws Interrupted naming `where` (e.g. "simulate frame 12") if a signal was received.
void throwIfInterrupted(const std::string& where);

/// @brief While alive, `path` is removed by the second signal's handler (a first signal unwinds
///        normally, and the owner removes it). At most kMaxRegisteredTemporaries at a time; the
///        ones beyond are still removed by unwinding.
class TemporaryRegistration {
 public:
  explicit TemporaryRegistration(const std::filesystem::path& path);
  ~TemporaryRegistration();
  TemporaryRegistration(const TemporaryRegistration&) = delete;
  TemporaryRegistration& operator=(const TemporaryRegistration&) = delete;

 private:
  int slot_ = -1;
};

/// Temporaries the second signal can remove at once (a command has a few open at a time).
inline constexpr int kMaxRegisteredTemporaries = 64;

}  // namespace fluidsound::io
