// io/audio_file.h — WAV and FLAC through libsndfile: 32-bit float by default, 16/24-bit PCM with
// TPDF dither on request, optional normalisation to a peak level or to a loudness target under a
// true-peak ceiling, channels named and without speaker positions, output by the rule of
// output_file.h; and reading back.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/loudness.h"

namespace fluidsound::io {

/// Audio in memory: one vector of samples per channel, all the same length.
struct AudioBuffer {
  double sampleRate = 48000.0;               ///< Hz
  std::vector<std::vector<float>> channels;  ///< samples per channel (Pa for renders, else file units)
  std::size_t frameCount() const { return channels.empty() ? 0 : channels.front().size(); }
};

enum class AudioFormat { Wav, Flac };

struct AudioWriteSettings {
  AudioFormat format = AudioFormat::Wav;
  int bitsPerSample = 32;                      ///< 32 (float; WAV only), 24 or 16 (PCM, TPDF-dithered)
  std::optional<double> normalizePeakDbfs;     ///< scale so the peak is at this level [dBFS], e.g. −1
  /// scale to this integrated loudness under a true-peak ceiling (not with normalizePeakDbfs)
  std::optional<io::LoudnessTarget> loudness;
  std::uint64_t ditherSeed = 1;                ///< seed of the TPDF dither noise (deterministic)
  /// channel c's name (its listener's), written to a WAV's iXML chunk; empty: none, else one per
  /// channel
  std::vector<std::string> channelNames;
};

/// What writing did to the signal.
struct AudioWriteReport {
  double inputPeak = 0.0;        ///< largest |sample| before scaling (input units, Pa for renders)
  double gain = 1.0;             ///< factor applied before writing (normalisation), [-]
  double outputPeakDbfs = 0.0;   ///< peak written, dB relative to full scale 1.0
  std::int64_t clippedSamples = 0;  ///< samples beyond full scale in a PCM file (clipped by the format)
  /// loudness of the samples written (after gain, dither and clipping), full scale 1.0
  io::LoudnessMeasurement written;
  bool truePeakLimited =
      false;  ///< the loudness target's gain was lowered to meet the true-peak ceiling
  bool loudnessUnmeasured = false;  ///< a loudness target was asked for, but the input has no
                                    ///< integrated loudness (silence, < 0.4 s): gain left at 1
};

/// @brief The format of a file name's extension, any case: `.flac` → Flac, `.wav` → Wav, any other
///        (or none) → nullopt: libsndfile is not asked to guess.
std::optional<AudioFormat> audioFormatFromPath(const std::filesystem::path& path);

/// The bytes of an audio file and what encoding did to the signal.
struct EncodedAudio {
  std::string bytes;
  AudioWriteReport report;
};

/// @brief Encodes audio in memory, as writeAudio() would write it (`path` only names it in errors).
/// @throws OutputError if libsndfile fails; std::invalid_argument on bad settings
EncodedAudio encodeAudio(const std::filesystem::path& path, const AudioBuffer& audio,
                         const AudioWriteSettings& settings);

/// @brief Writes audio by the output rule (output_file.h): atomically onto a regular file or a new
///        name, written through to a device, a FIFO or `-`. FLAC has no float samples: it is
///        written as 24-bit (or 16-bit) PCM. PCM output beyond full scale is clipped and counted in
///        the report (never silently). Three or more channels are written without speaker
///        positions (io/channel_layout.h).
/// @throws OutputError if the file cannot be written; std::invalid_argument on bad settings
AudioWriteReport writeAudio(const std::filesystem::path& path, const AudioBuffer& audio,
                            const AudioWriteSettings& settings);

/// @brief Reads any audio file libsndfile opens, as floats in file units (full scale 1.0 for PCM).
/// @throws InputError if the file is missing or not audio
AudioBuffer readAudio(const std::filesystem::path& path);

}  // namespace fluidsound::io
