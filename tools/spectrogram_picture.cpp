// tools/spectrogram_picture.cpp — see spectrogram_picture.h.
#include "tools/spectrogram_picture.h"

#include <vector>

#include "acoustics/analysis/spectrogram.h"
#include "io/interruption.h"

namespace fluidsound::tools {

std::string spectrogramPicture(const io::AudioBuffer& audio, const io::SpectrogramSettings& settings,
                               const std::string& title) {
  const std::vector<float> signal = io::spectrogramSignal(audio, settings);
  io::throwIfInterrupted("spectrogram");
  const acoustics::SpectrogramPower power =
      acoustics::pooledSpectrogramPower(signal, audio.sampleRate, io::spectrogramLayout(settings));
  io::throwIfInterrupted("spectrogram");
  return io::encodeSpectrogramPng(audio, settings, title, power);
}

}  // namespace fluidsound::tools
