// tests/support/command_runner.h — runs the real `fluidsound` executable (FLUIDSOUND_EXECUTABLE,
// defined for the tests in tests/CMakeLists.txt) and returns its exit status and its stderr.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <initializer_list>
#include <string>

namespace fluidsound::test {

struct CommandOutcome {
  int exitCode = -1;  ///< the exit status, or -1 if the process did not exit normally
  std::string err;    ///< everything written to stderr
};

/// `text` as one word for a POSIX shell.
inline std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// Runs `fluidsound ARGUMENTS…` (each argument passed as it is); stdout is discarded.
inline CommandOutcome runFluidsound(std::initializer_list<std::string> arguments) {
  std::string command = shellQuoted(FLUIDSOUND_EXECUTABLE);
  for (const std::string& argument : arguments) command.append(" ").append(shellQuoted(argument));
  command += " 2>&1 >/dev/null";  // stderr into the pipe, stdout away
  CommandOutcome outcome;
  std::FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return outcome;
  char buffer[4096];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, pipe)) > 0)
    outcome.err.append(buffer, count);
  const int status = ::pclose(pipe);
  outcome.exitCode = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
  return outcome;
}

}  // namespace fluidsound::test
