// io/file_kind.h — a file system entry's kind in words, for the one-line errors that refuse an
// input or an output that is not a regular file ("found a FIFO", "it is a folder").
#pragma once

#include <filesystem>
#include <string>

namespace fluidsound::io {

/// @brief "a regular file", "a folder", "a FIFO", "a character device", "a block device",
///        "a socket", "a symbolic link", "no such file"; "not a regular file" for any other kind.
std::string fileKindName(std::filesystem::file_type type);

}  // namespace fluidsound::io
