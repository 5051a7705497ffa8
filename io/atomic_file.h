// io/atomic_file.h — all-or-nothing output: write to a temporary file in the target's folder,
// then rename over the target, so a failed or interrupted run leaves no half-written file. Only
// for what the output rule replaces (output_file.h): a regular file, a new name, or a symlink's
// regular target (the link stays).
#pragma once

#include <filesystem>
#include <memory>

#include "io/interruption.h"

namespace fluidsound::io {

/// @brief A temporary path beside `target`; commit() renames it onto the target, and the
///        destructor removes the temporary if commit() was never called.
/// @par Example
///   AtomicFile out(path);  writeSomething(out.temporaryPath());  out.commit();
class AtomicFile {
 public:
  /// @throws OutputError if the target's folder does not exist or is not writable, or the target
  ///         is not a regular file or a new name (a folder, a device, a FIFO, a link to nothing)
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::filesystem::path& temporaryPath() const { return temporary_; }
  /// The file the temporary is renamed onto: the path given, or the regular file its link names.
  const std::filesystem::path& targetPath() const { return target_; }

  /// @throws OutputError if the rename fails
  void commit();

 private:
  std::filesystem::path shown_;   ///< as given, for messages
  std::filesystem::path target_;  ///< resolved
  std::filesystem::path temporary_;
  std::unique_ptr<TemporaryRegistration> registration_;  ///< a second signal removes temporary_
  bool committed_ = false;
};

}  // namespace fluidsound::io
