// io/vdb_file_check.h — the structure of a .vdb file checked before OpenVDB reads it: OpenVDB 10
// trusts every length in the file, so a corrupt one makes it allocate (and fill) up to 4 GiB, or
// std::bad_alloc, or read past a buffer, before any error (found by tests/fuzz/frame_vdb_fuzz).
// The one check every reader of a .vdb file (io/frame_surface.h) calls first.
#pragma once

#include <filesystem>

namespace fluidsound::io {

/// @brief Checks an OpenVDB file (format 222 … 224, as OpenVDB 10 writes with openvdb::io::File)
///        against the file's size: the magic number, the file's metadata, the grid descriptors
///        (at most 1024; every string length, count and offset within the file, each grid's
///        offsets in order), each grid's own metadata block and transform type. Every metadata
///        value must be what OpenVDB reads for its type: a fixed-size type's own size, and a
///        delayed-load table's node count, array sizes and blosc headers within the value. For
///        every float and Vec3 grid (a level set, a velocity; values saved full or as half
///        floats), also its transform, topology and every leaf's values; the grid named
///        `surface` must be a FloatGrid. Other grids' trees (points) are not checked.
/// @param path  the file; named in messages as given
/// @throws InputError naming the file and the part of it, e.g.
///         `0000.vdb: grid 0 name: expected a length within the file (at most 89000 bytes left),
///         found 4294967280`
void requireIntactVdbFile(const std::filesystem::path& path);

}  // namespace fluidsound::io
