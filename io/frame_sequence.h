// io/frame_sequence.h — the files of a frame sequence named by a pattern, as liquid caches name
// them (issue 21; docs/import.md): one frame-number token in the file name — printf's `%04d` or
// `%d`, Houdini's `$F4` or `$F`, Blender's `####` — or a folder, whose files are NNNN.vdb as
// `fluidsound simulate` writes them. Every frame from the first found to the last must be there.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fluidsound::io {

/// One file of a sequence.
struct SequenceFrame {
  int frame = 0;                ///< its frame number
  std::filesystem::path path;   ///< the file
  bool operator==(const SequenceFrame&) const = default;
};

/// @brief The files `pattern` names, relative to `folder` unless absolute, in frame order.
/// @param source  the file the pattern comes from and its field, for errors (e.g. "cache.json",
///                "frames")
/// @throws InputError naming `source`'s file and field: a pattern without exactly one frame token
///         (or with one outside the file name), a folder that does not exist, no file matching,
///         a frame missing between the first and the last (naming the file expected)
std::vector<SequenceFrame> frameSequence(const std::string& pattern, const std::filesystem::path& folder,
                                         const std::string& sourceFile, const std::string& field);

}  // namespace fluidsound::io
