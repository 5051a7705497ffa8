// io/output_file.h — the one rule of every output of every command (docs/cli.md, "Outputs"):
// a regular file or a new name is replaced atomically (temporary file beside it, then rename); a
// symlink is followed and its target replaced the same way if that is a regular file (the link
// stays); a character device, a FIFO, `-` (standard output) or a link through /proc
// (/dev/stdout, /dev/fd/N) is written through (opened and written, no temporary, no rename);
// anything else (a folder, a socket, a block device, a link to nothing) is refused with one line
// before any work.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace fluidsound::io {

/// How an output path is written.
enum class OutputKind {
  Replace,        ///< a regular file or a new name: temporary + rename
  WriteThrough,   ///< a character device or a FIFO: open and write
  StandardOutput  ///< `-`: written to file descriptor 1
};

struct OutputTarget {
  OutputKind kind = OutputKind::Replace;
  std::filesystem::path shown;  ///< the path as given, for messages
  std::filesystem::path file;   ///< where the bytes go: a symlink's target for Replace
};

/// @return true if `path` is `-`, standard output
bool isStandardOutput(const std::filesystem::path& path);

/// @brief Applies the rule to `path` without writing anything.
/// @throws OutputError (one line, naming the path) for what is refused, a missing or unwritable
///         folder, or an empty file name
OutputTarget resolveOutput(const std::filesystem::path& path);

/// @brief Writes `bytes` to `path` by the rule.
/// @throws OutputError if it cannot be written (then a replaced file keeps its old content)
void writeOutputFile(const std::filesystem::path& path, std::string_view bytes);

/// @brief Several outputs of one command, all or nothing: add() writes each replaced file to its
///        temporary; commit() writes the write-through ones, then renames every temporary onto its
///        target. Destroyed without commit(), it removes every temporary and writes nothing.
class OutputBatch {
 public:
  OutputBatch();
  ~OutputBatch();
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;

  /// @throws OutputError
  void add(const std::filesystem::path& path, std::string bytes);
  /// @throws OutputError
  void commit();

 private:
  struct Pending;
  std::vector<std::unique_ptr<Pending>> pending_;
};

}  // namespace fluidsound::io
