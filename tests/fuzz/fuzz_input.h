// tests/fuzz/fuzz_input.h — what every libFuzzer harness of tests/fuzz/ shares: the fuzz input
// written to a file (the readers take paths) and the one outcome a bad input may have.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace fluidsound::fuzz {

/// @brief One file in a folder of this process's own under the temporary folder ($TMPDIR, else
///        /tmp), rewritten with each input; the folder is removed at exit (not after a crash:
///        tools/test.sh points TMPDIR into build-fuzz/ for that).
class InputFile {
 public:
  /// @param name  the file's name; its extension chooses the reader (`mesh.obj`, `mesh.ply`)
  explicit InputFile(const std::string& name) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "fluidsound-fuzz-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      std::perror("fuzz: cannot make a temporary folder");
      std::abort();
    }
    folder_ = pattern;
    path_ = folder_ / name;
  }
  ~InputFile() {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// @brief Replaces the file's content with the `size` bytes at `data`.
  /// @return the file's path
  const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) const {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
      std::perror("fuzz: cannot write the input file");
      std::abort();
    }
    return path_;
  }

  /// @brief Writes a fixed file beside the input, for inputs that name other files (a scene's
  ///        meshes).
  void writeBeside(const std::string& name, std::string_view text) const {
    std::ofstream out(folder_ / name, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
      std::perror("fuzz: cannot write a file beside the input");
      std::abort();
    }
  }

 private:
  std::filesystem::path folder_;
  std::filesystem::path path_;
};

/// @brief Stops the run as a crash (libFuzzer saves the input) with a message on standard error.
[[noreturn]] inline void fail(std::string_view what) {
  std::fprintf(stderr, "fuzz: %.*s\n", static_cast<int>(what.size()), what.data());
  std::abort();
}

/// @brief The checks every refusal must pass (common.md): its message is one line that names
///        the file it is about.
/// @param error  an io::InputError or io::OutputError a reader threw
/// @param file   the path the reader was given, as it names it
inline void requireOneLineNaming(const std::exception& error, const std::string& file) {
  const std::string_view message = error.what();
  if (message.find('\n') != std::string_view::npos)
    fail("an error message of more than one line: " + std::string(message));
  if (message.find(file) == std::string_view::npos)
    fail("an error message that does not name " + file + ": " + std::string(message));
}

}  // namespace fluidsound::fuzz
