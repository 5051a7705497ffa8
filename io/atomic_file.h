// io/atomic_file.h — all-or-nothing output: write to a temporary file in the target's folder,
// then rename over the target, so a failed or interrupted run leaves no half-written file.
#pragma once

#include <filesystem>

namespace fluidsound::io {

/// @brief A temporary path beside `target`; commit() renames it onto the target, and the
///        destructor removes the temporary if commit() was never called.
/// @par Example
///   AtomicFile out(path);  writeSomething(out.temporaryPath());  out.commit();
class AtomicFile {
 public:
  /// @throws OutputError if the target's folder does not exist or is not writable
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::filesystem::path& temporaryPath() const { return temporary_; }
  const std::filesystem::path& targetPath() const { return target_; }

  /// @throws OutputError if the rename fails
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  bool committed_ = false;
};

}  // namespace fluidsound::io
