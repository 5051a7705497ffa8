// tools/spectrogram_picture.h — the spectrogram PNG of a render: the picture's signal and grid
// (io/spectrogram_image.h), the pooled STFT power on it (acoustics/analysis/spectrogram.h), drawn
// by io; for `synth`, `run` and `spectrogram`.
#pragma once

#include <string>

#include "io/audio_file.h"
#include "io/spectrogram_image.h"

namespace fluidsound::tools {

/// @brief The PNG bytes of the spectrogram of `audio`, titled `title` (docs/spectrogram.md).
/// @throws std::invalid_argument as io::spectrogramSignal(); io::Interrupted after a signal
std::string spectrogramPicture(const io::AudioBuffer& audio, const io::SpectrogramSettings& settings,
                               const std::string& title);

}  // namespace fluidsound::tools
