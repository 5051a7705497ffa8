// io/vdb_header_check.h — checks the structure of an OpenVDB file's header before OpenVDB reads
// it: every length and offset must lie inside the file. OpenVDB trusts them (a damaged string
// length makes it allocate and zero gigabytes before the read fails), so a truncated or garbage
// frame must be refused here, with a one-line error, not by std::bad_alloc or the kernel.
#pragma once

#include <filesystem>

namespace fluidsound::io {

/// @brief Walks the header of the VDB file at `path` as OpenVDB 10 writes it with grid offsets
///        (file format 222–224): magic, version, UUID, file metadata, then per grid its
///        descriptor (name, type, instance parent, three offsets), its metadata and its transform's
///        type name, checking that each length and offset stays within the file.
/// @throws InputError naming the file, the byte offset and what was wrong
void requireIntactVdbHeader(const std::filesystem::path& path);

}  // namespace fluidsound::io
