// io/interruption.cpp — signal handlers and the registry of temporaries (see interruption.h).
//
// Global state, the documented exception to the project's rule: a signal handler can reach
// nothing else. It is only (1) the first signal received, a lock-free atomic int, and (2) a fixed
// table of temporary paths, each slot guarded by an atomic state, so the handler reads only
// complete paths and calls only async-signal-safe functions (unlink, write, _exit).
#include "io/interruption.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace fluidsound::io {
namespace {

/// Longest temporary path the second signal can remove (PATH_MAX on Linux).
constexpr std::size_t kMaxPathBytes = 4096;

enum SlotState : int { kFree = 0, kFilling = 1, kReady = 2 };

struct TemporarySlot {
  std::atomic<int> state{kFree};
  char path[kMaxPathBytes];
};

std::atomic<int> firstSignal{0};
std::atomic<int> signalsReceived{0};
TemporarySlot temporaries[kMaxRegisteredTemporaries];

static_assert(std::atomic<int>::is_always_lock_free, "the handler needs a lock-free atomic");

const char* signalName(int signalNumber) {
  switch (signalNumber) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "a signal";
  }
}

void writeToStderr(const char* text) {
  ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;  // nothing to do about a failed message while ending
}

void onSignal(int signalNumber) {
  int none = 0;
  firstSignal.compare_exchange_strong(none, signalNumber);
  if (signalsReceived.fetch_add(1) == 0) return;  // the first: the loops will notice it
  // The second: the command did not end in time (a blocked write, a long step). Remove what is
  // registered and end now.
  for (TemporarySlot& slot : temporaries)
    if (slot.state.load() == kReady) ::unlink(slot.path);
  writeToStderr("fluidsound: interrupted again (");
  writeToStderr(signalName(signalNumber));
  writeToStderr("); temporary files removed, nothing else written\n");
  ::_exit(128 + signalNumber);
}

}  // namespace

Interrupted::Interrupted(int signalNumber, const std::string& where, const std::string& aftermath)
    : std::runtime_error(std::string("interrupted (") + signalName(signalNumber) + ") at " + where +
                         (aftermath.empty() ? std::string() : "; " + aftermath)),
      signal_(signalNumber),
      where_(where),
      aftermath_(aftermath) {}

void installInterruptionHandlers() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // system calls of libraries resume; the loops check the flag
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGPIPE, &ignore, nullptr);
}

int interruptionSignal() { return firstSignal.load(std::memory_order_relaxed); }

void throwIfInterrupted(const std::string& where) {
  if (const int signalNumber = interruptionSignal(); signalNumber != 0)
    throw Interrupted(signalNumber, where);
}

TemporaryRegistration::TemporaryRegistration(const std::filesystem::path& path) {
  const std::string& text = path.native();
  if (text.size() >= kMaxPathBytes) return;
  for (int s = 0; s < kMaxRegisteredTemporaries; ++s) {
    int expected = kFree;
    if (!temporaries[s].state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(temporaries[s].path, text.c_str(), text.size() + 1);
    temporaries[s].state.store(kReady);
    slot_ = s;
    return;
  }
}

TemporaryRegistration::~TemporaryRegistration() {
  if (slot_ >= 0) temporaries[slot_].state.store(kFree);
}

}  // namespace fluidsound::io
