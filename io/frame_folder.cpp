// io/frame_folder.cpp — see frame_folder.h.
#include "io/frame_folder.h"

#include <signal.h>  // kill(pid, 0): does the process exist

#include <cerrno>
#include <cstdio>
#include <optional>
#include <system_error>

#include "io/file_kind.h"
#include "io/input_error.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kExtensions[] = {"vdb", "ply"};
/// More digits than any frame number a scene allows (scene.md: at most 10⁶ frames).
constexpr std::size_t kMaxFrameDigits = 9;

/// A frame file's number and extension.
struct FrameName {
  int frame = 0;
  std::string_view extension;
};

/// The frame `name` is the file of, if it is exactly frameFileName(frame, extension).
std::optional<FrameName> parseFrameName(std::string_view name) {
  const std::size_t dot = name.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot > kMaxFrameDigits) return std::nullopt;
  int frame = 0;
  for (std::size_t i = 0; i < dot; ++i) {
    if (name[i] < '0' || name[i] > '9') return std::nullopt;
    frame = frame * 10 + (name[i] - '0');
  }
  for (const std::string_view extension : kExtensions)
    if (name.substr(dot + 1) == extension && frameFileName(frame, extension) == name)
      return FrameName{frame, extension};
  return std::nullopt;
}

/// The process id in a temporary's name `.FRAME.tmp-PID-HEX16` (atomic_file.cpp), if `name` is one.
std::optional<long> temporaryOwner(std::string_view name) {
  constexpr std::string_view kTag = ".tmp-";
  constexpr std::size_t kSuffixDigits = 16;
  const std::size_t tag = name.find(kTag);
  if (name.size() < 2 || name[0] != '.' || tag == std::string_view::npos) return std::nullopt;
  if (!parseFrameName(name.substr(1, tag - 1))) return std::nullopt;
  const std::string_view rest = name.substr(tag + kTag.size());
  const std::size_t dash = rest.find('-');
  if (dash == 0 || dash == std::string_view::npos || dash > kMaxFrameDigits ||
      rest.size() - dash - 1 != kSuffixDigits)
    return std::nullopt;
  long pid = 0;
  for (std::size_t i = 0; i < dash; ++i) {
    if (rest[i] < '0' || rest[i] > '9') return std::nullopt;
    pid = pid * 10 + (rest[i] - '0');
  }
  for (const char c : rest.substr(dash + 1))
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return std::nullopt;
  return pid;
}

bool processHasEnded(long pid) { return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

}  // namespace

std::string frameFileName(int frame, std::string_view extension) {
  char digits[16];
  std::snprintf(digits, sizeof digits, "%04d", frame);
  return std::string(digits) + "." + std::string(extension);
}

FrameFolderCleanup clearStaleFrames(const fs::path& folder, const FrameWritten& written) {
  FrameFolderCleanup result;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return result;
  std::vector<fs::path> remove;
  fs::directory_iterator entries(folder, ec);
  for (; !ec && entries != fs::directory_iterator(); entries.increment(ec)) {
    const fs::path& path = entries->path();
    const std::string name = path.filename().string();
    std::error_code statusError;
    const fs::file_type type =
        entries->symlink_status(statusError).type();  // the entry, not a link's target
    if (statusError)
      throw OutputError(path.string() + ": cannot inspect: " + statusError.message());
    const std::optional<FrameName> frame = parseFrameName(name);
    const std::optional<long> owner = frame ? std::nullopt : temporaryOwner(name);
    if (frame && type == fs::file_type::symlink) {
      remove.push_back(path);
    } else if (frame && type == fs::file_type::regular) {
      if (!written(frame->frame, frame->extension)) remove.push_back(path);
    } else if (frame && written(frame->frame, frame->extension)) {
      throw OutputError(
          path.string() + ": cannot write the frame: it is " + fileKindName(type) +
          ", not a file a simulation wrote; remove it or choose another output folder");
    } else if (owner && type == fs::file_type::regular && processHasEnded(*owner)) {
      remove.push_back(path);
    } else {
      result.foreign.push_back(path);
    }
  }
  if (ec) throw OutputError(folder.string() + ": cannot list the folder: " + ec.message());
  for (const fs::path& path : remove) {
    fs::remove(path, ec);  // a link itself: std::filesystem::remove does not follow it
    if (ec) throw OutputError(path.string() + ": cannot remove the stale frame: " + ec.message());
    result.removed.push_back(path);
  }
  return result;
}

}  // namespace fluidsound::io
