// io/text_file.cpp — atomic text output (see text_file.h).
#include "io/text_file.h"

#include <unistd.h>

#include <fstream>

#include "io/atomic_file.h"
#include "io/input_error.h"

namespace fluidsound::io {

void writeTextFile(const std::filesystem::path& path, std::string_view text) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temporaryPath(), std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) throw OutputError(path.string() + ": cannot write the file");
  }
  file.commit();
}

void requireWritableFolder(const std::filesystem::path& path) {
  const std::filesystem::path folder =
      path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec))
    throw OutputError(path.string() + ": cannot write: folder " + folder.string() + " does not exist");
  if (::access(folder.c_str(), W_OK) != 0)
    throw OutputError(path.string() + ": cannot write: folder " + folder.string() + " is not writable");
  if (std::filesystem::is_directory(path, ec))
    throw OutputError(path.string() + ": cannot write: it is a folder");
}

}  // namespace fluidsound::io
