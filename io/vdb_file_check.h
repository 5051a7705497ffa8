// io/vdb_file_check.h — the structure of a .vdb file's header checked before OpenVDB reads it:
// OpenVDB 10 trusts every length in the file, so a corrupt one makes it allocate (and fill) up to
// 4 GiB, or std::bad_alloc, before any error (found by tests/fuzz/frame_vdb_fuzz).
#pragma once

#include <filesystem>

namespace fluidsound::io {

/// @brief Checks the header of an OpenVDB file (format 222 … 224, as OpenVDB 10 writes with
///        openvdb::io::File) against the file's size: the magic number, the file's metadata, the
///        grid descriptors (every string length, count and offset within the file, each grid's
///        offsets in order) and each grid's own metadata block. The grids' trees are not checked.
/// @param path  the file; named in messages as given
/// @throws InputError naming the file and the part of the header, e.g.
///         `0000.vdb: grid 0 name: expected a length within the file (at most 89000 bytes left),
///         found 4294967280`
void requireIntactVdbFile(const std::filesystem::path& path);

}  // namespace fluidsound::io
