// io/frame_folder.h — the per-frame files of OUTDIR/frames (frame_files.h): their names, NNNN.vdb
// and NNNN.ply (the frame number, at least 4 digits), and clearing the frames another run left
// there, so that a folder never mixes the frames of two simulations.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fluidsound::io {

/// "0003.vdb" for frame 3 and extension "vdb"; "12345.ply" past 9999.
std::string frameFileName(int frame, std::string_view extension);

/// What clearStaleFrames() did.
struct FrameFolderCleanup {
  std::vector<std::filesystem::path> removed;  ///< stale frames, links and temporaries, removed
  std::vector<std::filesystem::path> foreign;  ///< entries that are not frames, left in place
};

/// Whether the coming simulation writes frame `frame` with `extension` ("vdb" or "ply").
using FrameWritten = std::function<bool(int frame, std::string_view extension)>;

/// @brief Prepares `folder` for a simulation that writes the frames `written` accepts. Removes
///        every regular file named like a frame that it will not write; every symbolic link named
///        like a frame (the link, never its target: the frames written are then regular files);
///        and the hidden temporaries of frames (`.NNNN.vdb.tmp-PID-…`, io/atomic_file.h) of
///        processes that have ended. Anything else (other names, a live process's temporaries,
///        a folder or FIFO named like a frame it will not write) is left in place and listed in
///        `foreign`. A missing folder is empty.
/// @throws OutputError, before anything is removed, if an entry named like a frame it will write
///         is neither a regular file nor a symbolic link (a folder, FIFO, device or socket): not
///         ours to replace; or if the folder cannot be listed or an entry removed.
FrameFolderCleanup clearStaleFrames(const std::filesystem::path& folder,
                                    const FrameWritten& written);

}  // namespace fluidsound::io
