// io/output_file.cpp — the output rule (see output_file.h).
#include "io/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <system_error>
#include <thread>
#include <utility>

#include "io/atomic_file.h"
#include "io/file_kind.h"
#include "io/input_error.h"
#include "io/interruption.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

OutputError cannotWrite(const fs::path& path, const std::string& reason) {
  return OutputError(path.string() + ": cannot write: " + reason);
}

std::string errnoText(int error) { return std::generic_category().message(error); }

/// What is refused, in words, or empty for a kind the rule accepts.
std::string refusedKind(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory:
      return "it is a folder";
    case fs::file_type::block:
    case fs::file_type::socket:
      return "it is " + fileKindName(type) + ", which is never replaced";
    case fs::file_type::regular:
    case fs::file_type::character:
    case fs::file_type::fifo:
    case fs::file_type::not_found:
      return {};
    default:
      return "it is not a regular file, a character device or a FIFO";
  }
}

/// The folder a new or replaced file goes into must exist and be writable.
void requireWritableFolderOf(const fs::path& shown, const fs::path& file) {
  const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  std::error_code ec;
  const fs::file_status status = fs::status(folder, ec);
  if (status.type() == fs::file_type::not_found)
    throw cannotWrite(shown, "folder '" + folder.string() + "' does not exist");
  if (status.type() != fs::file_type::directory)
    throw cannotWrite(shown, "'" + folder.string() + "' is not a folder");
  if (::access(folder.c_str(), W_OK) != 0)
    throw cannotWrite(shown,
                      "folder '" + folder.string() + "' is not writable: " + errnoText(errno));
}

/// True if following `path`'s links passes through /proc (/dev/stdout → /proc/self/fd/1): such a
/// link names an open file of a process, not a place, so it is written through even when it
/// ends at a regular file (a shell's `> file`), and nothing is made beside it.
bool linksThroughProc(const fs::path& path) {
  constexpr int kMaxLinks = 40;  // Linux's own limit (MAXSYMLINKS)
  fs::path at = path;
  std::error_code ec;
  for (int hop = 0; hop < kMaxLinks && fs::is_symlink(at, ec); ++hop) {
    const fs::path next = fs::read_symlink(at, ec);
    if (ec) return false;
    at = next.is_absolute() ? next : at.parent_path() / next;
    if (at.lexically_normal().string().starts_with("/proc/")) return true;
  }
  return false;
}

/// Writes all of `bytes` to `descriptor`, resuming after partial writes and EINTR.
/// @return 0, or the errno of the failed write
int writeAll(int descriptor, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(descriptor, bytes.data(), bytes.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
  return 0;
}

/// Opens a device or a FIFO for writing. No O_CREAT, no O_TRUNC: it is written, never made or
/// changed. A FIFO without a reader would block open() (restarted after a signal), so it is opened
/// without blocking and retried every 20 ms until a reader comes or a signal ends the command.
int openForWritingThrough(const OutputTarget& target) {
  constexpr auto kReaderPoll = std::chrono::milliseconds(20);
  while (true) {
    const int descriptor =
        ::open(target.file.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (descriptor >= 0) {
      ::fcntl(descriptor, F_SETFL,
              ::fcntl(descriptor, F_GETFL) & ~O_NONBLOCK);  // then block as usual
      return descriptor;
    }
    if (errno != ENXIO && errno != EINTR) throw cannotWrite(target.shown, errnoText(errno));
    throwIfInterrupted("waiting for a reader of " + target.shown.string());
    std::this_thread::sleep_for(kReaderPoll);
  }
}

void writeThrough(const OutputTarget& target, std::string_view bytes) {
  if (target.kind == OutputKind::StandardOutput) {
    std::fflush(stdout);  // nothing the program printed may come after the bytes
    if (const int error = writeAll(STDOUT_FILENO, bytes); error != 0)
      throw OutputError("standard output: cannot write: " + errnoText(error));
    return;
  }
  const int descriptor = openForWritingThrough(target);
  const int writeError = writeAll(descriptor, bytes);
  const int closeError = ::close(descriptor) == 0 ? 0 : errno;
  if (writeError != 0 || closeError != 0)
    throw cannotWrite(target.shown, errnoText(writeError != 0 ? writeError : closeError));
}

void writeTemporary(const AtomicFile& file, std::string_view bytes) {
  const int descriptor = ::open(file.temporaryPath().c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (descriptor < 0) throw cannotWrite(file.targetPath(), errnoText(errno));
  const int writeError = writeAll(descriptor, bytes);
  const int closeError = ::close(descriptor) == 0 ? 0 : errno;
  if (writeError != 0 || closeError != 0)
    throw cannotWrite(file.targetPath(), errnoText(writeError != 0 ? writeError : closeError));
}

}  // namespace

bool isStandardOutput(const fs::path& path) { return path.native() == "-"; }

OutputTarget resolveOutput(const fs::path& path) {
  if (isStandardOutput(path)) return {OutputKind::StandardOutput, path, path};
  if (path.empty() || path.filename().empty() || path.filename() == "." || path.filename() == "..")
    throw cannotWrite(path, "not a file name");
  std::error_code ec;
  const fs::file_status own = fs::symlink_status(path, ec);
  const fs::file_status followed = fs::status(path, ec);
  const bool link = own.type() == fs::file_type::symlink;
  if (link && followed.type() == fs::file_type::not_found)
    throw cannotWrite(path, "it is a symbolic link to nothing (its target is not made)");
  if (const std::string refused = refusedKind(followed.type()); !refused.empty())
    throw cannotWrite(path, refused);
  const bool stream = followed.type() == fs::file_type::character ||
                      followed.type() == fs::file_type::fifo || (link && linksThroughProc(path));
  if (stream) {
    if (::access(path.c_str(), W_OK) != 0) throw cannotWrite(path, errnoText(errno));
    return {OutputKind::WriteThrough, path, path};
  }
  OutputTarget target{OutputKind::Replace, path, path};
  if (link) {
    target.file = fs::canonical(path, ec);  // the link stays; its regular target is replaced
    if (ec) throw cannotWrite(path, "its symbolic link cannot be followed: " + ec.message());
  }
  requireWritableFolderOf(path, target.file);
  return target;
}

void writeOutputFile(const fs::path& path, std::string_view bytes) {
  OutputBatch batch;
  batch.add(path, std::string(bytes));
  batch.commit();
}

struct OutputBatch::Pending {
  OutputTarget target;
  std::string bytes;                 ///< for a write-through target, until commit()
  std::unique_ptr<AtomicFile> file;  ///< for a replaced one: its written temporary
};

OutputBatch::OutputBatch() = default;
OutputBatch::~OutputBatch() = default;

void OutputBatch::add(const fs::path& path, std::string bytes) {
  auto pending = std::make_unique<Pending>();
  pending->target = resolveOutput(path);
  if (pending->target.kind == OutputKind::Replace) {
    pending->file = std::make_unique<AtomicFile>(path);
    writeTemporary(*pending->file, bytes);
  } else {
    pending->bytes = std::move(bytes);
  }
  pending_.push_back(std::move(pending));
}

void OutputBatch::commit() {
  // Write-through first: it is what can fail (a full device, a closed pipe); a rename seldom does.
  for (const auto& pending : pending_)
    if (!pending->file) writeThrough(pending->target, pending->bytes);
  for (const auto& pending : pending_)
    if (pending->file) pending->file->commit();
  pending_.clear();
}

}  // namespace fluidsound::io
