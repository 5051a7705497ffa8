// tools/audio_options.h — the audio output options of `synth` and `run` (--rate, --format, --bits,
// --normalize, --loudness, --true-peak), in one place so the two commands never drift; the
// write settings they mean, and what the run report says about the audio written.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/audio_file.h"

namespace CLI {
class App;
}

namespace fluidsound::tools {

class RunReport;

struct AudioOutputOptions {
  std::optional<double> sampleRate;  ///< --rate [Hz]; default: the bubble file's sample_rate
  std::string format;                ///< --format wav | flac; default from the output's extension
  int bits = 0;                      ///< --bits 16 | 24 | 32; default 32 (WAV), 24 (FLAC)
  std::optional<double> normalizeDbfs;  ///< --normalize: peak level [dBFS]
  std::optional<double> loudnessLufs;   ///< --loudness: integrated loudness target [LUFS]
  double truePeakDbtp = -1.0;           ///< --true-peak: ceiling with --loudness [dBTP] (EBU R 128)
};

/// Adds the audio output options to a subcommand (docs/cli.md, `synth`).
void addAudioOutputOptions(CLI::App& command, AudioOutputOptions& options);

/// @brief The write settings the options mean for `output`, naming channel c `channelNames[c]`:
///        the format and bits of audioLayout() (command_options.h), checked before any work.
/// @throws CLI::ValidationError (exit 2) naming --output, --format or --bits
io::AudioWriteSettings audioWriteSettings(const AudioOutputOptions& options,
                                          const std::filesystem::path& output,
                                          std::vector<std::string> channelNames);

/// Every option's value as one line of text, for `run`'s record of what its synth stage used.
std::string audioOptionsFingerprint(const AudioOutputOptions& options);

/// @brief Records the audio written in the report: settings (format, bits, normalisation) and
///        results: the gain and the scale it leaves (`1.0 = 1 Pa = 94.0 dB SPL` when the samples
///        keep their calibrated pascals), the integrated loudness and true peak measured on what
///        was written, whether the true-peak ceiling lowered the gain, and the channel names.
void reportAudioOutput(RunReport& report, const io::AudioWriteSettings& settings,
                       const io::AudioWriteReport& written);

/// Prints the notes and warnings a sound designer needs about the audio written (clipping, a
/// float peak above 0 dBFS, the true-peak ceiling, a loudness that could not be measured).
void warnAboutAudioOutput(const io::AudioWriteReport& written, bool quiet);

}  // namespace fluidsound::tools
