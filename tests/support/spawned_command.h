// tests/support/spawned_command.h — the real `fluidsound` executable started in the background,
// with stdout and stderr going to files, so a test can wait for a line and send it a signal.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "support/special_files.h"

extern char** environ;

namespace fluidsound::test {

class SpawnedFluidsound {
 public:
  /// Starts `fluidsound ARGUMENTS…`; stdout to `stdoutFile`, stderr to `stderrFile`.
  SpawnedFluidsound(const std::vector<std::string>& arguments, const std::filesystem::path& stdoutFile,
                    const std::filesystem::path& stderrFile)
      : stderrFile_(stderrFile) {
    std::vector<std::string> words{FLUIDSOUND_EXECUTABLE};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, stdoutFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderrFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
  }
  ~SpawnedFluidsound() {
    if (pid_ > 0 && !waited_) {
      ::kill(pid_, SIGKILL);
      wait();
    }
  }
  SpawnedFluidsound(const SpawnedFluidsound&) = delete;
  SpawnedFluidsound& operator=(const SpawnedFluidsound&) = delete;

  bool started() const { return pid_ > 0; }

  /// @return true once stderr holds `text`, false after `timeout` or if the process ended first
  bool waitForStderr(const std::string& text, std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      if (fileBytes(stderrFile_).find(text) != std::string::npos) return true;
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        waited_ = true;
        status_ = status;
        return fileBytes(stderrFile_).find(text) != std::string::npos;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }

  /// @return true once the process has installed its SIGINT and SIGTERM handlers (the SigCgt
  ///         mask of /proc/PID/status, read only) and, if `syscall` ≥ 0, its main thread is in
  ///         that system call (the first field of /proc/PID/syscall); false after `timeout` or
  ///         if it ended. A signal sent then reaches the handler, however loaded the machine.
  bool waitUntilHandling(std::chrono::milliseconds timeout, int syscall = -1) const {
    const auto end = std::chrono::steady_clock::now() + timeout;
    const std::string proc = "/proc/" + std::to_string(pid_);
    const unsigned long long wanted = (1ull << (SIGINT - 1)) | (1ull << (SIGTERM - 1));
    while (std::chrono::steady_clock::now() < end) {
      const std::string status = fileBytes(proc + "/status");
      const std::size_t at = status.find("SigCgt:");
      if (at == std::string::npos) return false;  // ended (or no /proc)
      const unsigned long long caught = std::stoull(status.substr(at + 7), nullptr, 16);
      if ((caught & wanted) == wanted &&
          (syscall < 0 || fileBytes(proc + "/syscall").starts_with(std::to_string(syscall) + " ")))
        return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
  }

  void signal(int signalNumber) const { ::kill(pid_, signalNumber); }

  /// @return the exit code, or -1 if the process did not exit normally
  int wait() {
    if (!waited_) {
      ::waitpid(pid_, &status_, 0);
      waited_ = true;
    }
    return WIFEXITED(status_) ? WEXITSTATUS(status_) : -1;
  }

  std::string err() const { return fileBytes(stderrFile_); }

 private:
  std::filesystem::path stderrFile_;
  pid_t pid_ = -1;
  int status_ = 0;
  bool waited_ = false;
};

}  // namespace fluidsound::test
