// io/text_file.h — writing small text outputs (JSON reports) by the output rule (output_file.h).
#pragma once

#include <filesystem>
#include <string_view>

namespace fluidsound::io {

/// @brief Writes `text` to `path` by the output rule: atomically onto a regular file or a new
///        name, written through to a character device, a FIFO or `-`.
/// @throws OutputError if it cannot be written or the path is refused
void writeTextFile(const std::filesystem::path& path, std::string_view text);

/// @brief Checks, before any work, that `path` could be written by the output rule: a new name or
///        a regular file (or a symlink to one) in an existing, writable folder, a character
///        device, a FIFO or `-`; never a folder, a socket, a block device or a link to nothing.
/// @throws OutputError naming the path and what is wrong
void requireWritableFolder(const std::filesystem::path& path);

}  // namespace fluidsound::io
