// io/text_file.h — writing small text outputs (JSON reports) atomically.
#pragma once

#include <filesystem>
#include <string_view>

namespace fluidsound::io {

/// @brief Writes `text` to `path` through a temporary file in the same folder and a rename.
/// @throws OutputError if it cannot be written
void writeTextFile(const std::filesystem::path& path, std::string_view text);

/// @brief Checks, before any work, that `path` could be written: its folder exists and is
///        writable, and `path` itself is not a folder.
/// @throws OutputError naming the path and what is wrong
void requireWritableFolder(const std::filesystem::path& path);

}  // namespace fluidsound::io
