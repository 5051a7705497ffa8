// io/bubble_track_file.h — reads and writes `fluidsound.bubbles/1` (DESIGN.md; docs/bubbles-format.md),
// validating every field; errors name the file, the JSON path and what was expected.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "acoustics/bubble/bubble_track.h"

namespace fluidsound::io {

/// Whether every track sample must carry `transfer` values. `Optional` is for the transfer
/// stage, whose input (written by `fluidsound simulate`) has depths but no transfer yet: then
/// either no sample has `transfer` (TrackSample::transfer stays empty) or every sample has it.
enum class TransferValues { Required, Optional };

/// @brief Parses a `fluidsound.bubbles/1` document.
/// @param text      the JSON text
/// @param fileName  used in error messages only
/// @throws InputError on malformed JSON, a wrong format tag, a missing or out-of-range field,
///         unsorted track samples, a transfer list of the wrong length, or an unknown key among
///         the fields the format defines (extra fields are allowed only where docs/ say so)
/// @note Every track sample must have `transfer` (TransferValues::Required).
acoustics::BubbleTrackSet parseBubbleTracks(std::string_view text, const std::string& fileName);

/// @brief As above, with `transfer` required or optional (all or nothing).
acoustics::BubbleTrackSet parseBubbleTracks(std::string_view text, const std::string& fileName,
                                            TransferValues transfer);

/// The input path that means standard input (as in sox and ffmpeg).
inline constexpr const char* kStandardInput = "-";

/// @brief Reads and parses a bubble-track file (`transfer` required in every track sample); the
///        path `-` reads standard input, named "standard input" in errors.
/// @throws InputError if the file is missing, not a regular file (a FIFO, device, folder) or
///         unreadable, or as parseBubbleTracks
acoustics::BubbleTrackSet readBubbleTracks(const std::filesystem::path& path);

/// @brief As above, with `transfer` required or optional (all or nothing).
acoustics::BubbleTrackSet readBubbleTracks(const std::filesystem::path& path,
                                           TransferValues transfer);

/// @brief Writes a bubble-track file atomically (temporary file, then rename), in a form that
///        parseBubbleTracks reads back to an equal BubbleTrackSet (numbers exact). Samples with an
///        empty `transfer` are written without it (the output of `fluidsound simulate`).
/// @throws OutputError if it cannot be written
/// @throws std::invalid_argument if `tracks` breaks the format (NaN, depth ≤ radius, …): the
///         message is the InputError parseBubbleTracks would give; nothing is written
void writeBubbleTracks(const std::filesystem::path& path, const acoustics::BubbleTrackSet& tracks);

}  // namespace fluidsound::io
