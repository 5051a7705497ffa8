// io/hrir_file.h — reads a head's measured impulse responses from a SOFA file (AES69-2015,
// SimpleFreeFieldHRIR) through libmysofa (Debian libmysofa-dev, BSD-3), whose runtime package ships
// the MIT KEMAR set (Gardner & Martin 1995). docs/binaural.md.
#pragma once

#include <filesystem>
#include <optional>

#include "acoustics/binaural/hrir_table.h"

namespace fluidsound::io {

/// The MIT KEMAR set (normal pinna) as Debian's libmysofa1 installs it.
std::filesystem::path defaultHrirFile();

/// @brief The impulse responses of `sofa`, its source positions as unit vectors in the head's frame
///        (x ahead, y left, z up) and its two receivers as the left and right ear; resampled to
///        `sampleRate` [Hz] when given and different from the file's (libmysofa's resampler,
///        Speex's windowed sinc), the delays kept in seconds.
/// @throws InputError naming the file and what was expected: missing, not a regular file or
///         unreadable, not a SOFA HRIR set libmysofa accepts, not two receivers, no measurement,
///         a rate libmysofa cannot resample to
acoustics::HrirTable readHrirTable(const std::filesystem::path& sofa,
                                   std::optional<double> sampleRate = std::nullopt);

}  // namespace fluidsound::io
