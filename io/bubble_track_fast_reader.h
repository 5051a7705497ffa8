// io/bubble_track_fast_reader.h — transfer and synthesis input: a single-pass reader of
// `fluidsound.bubbles/1` for the documents fluidsound writes itself (tens of thousands of track
// samples), without building a JSON tree; anything it does not fully understand is left to the
// validating reader of bubble_track_file.h, which gives the error messages.
#pragma once

#include <optional>
#include <string_view>

#include "acoustics/bubble/bubble_track.h"
#include "io/bubble_track_file.h"

namespace fluidsound::io {

/// @brief Parses `text` as `fluidsound.bubbles/1` when it is a plain, valid document: the format's
///        own keys only (any order, each once), ASCII strings without escapes, and every field
///        within the range parseBubbleTracks requires.
/// @return the same BubbleTrackSet parseBubbleTracks returns for `text`, or std::nullopt when the
///         document is invalid or uses anything outside that subset (extension keys, escapes,
///         duplicate keys, `-0` written as an integer, numbers beyond the double range): the caller
///         then runs parseBubbleTracks, which accepts it or names the problem.
/// @note Numbers are read with std::from_chars, correctly rounded as nlohmann-json's strtod, so
///       the values are bit-identical (tests/io/bubble_track_fast_reader_test.cpp).
std::optional<acoustics::BubbleTrackSet> parsePlainBubbleTracks(std::string_view text, TransferValues transfer);

}  // namespace fluidsound::io
