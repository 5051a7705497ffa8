// tools/synth_command.h — `fluidsound synth BUBBLES.json -o OUT.wav`: bubble tracks → audio file,
// its spectrogram (optional) and a report.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/bubble/oscillator_model.h"
#include "tools/audio_options.h"
#include "tools/command_options.h"

namespace fluidsound::tools {

struct SynthOptions {
  CommonOptions common;
  std::string input;                 ///< bubble-track file
  std::string output;                ///< .wav or .flac, - (stdout), a device or a FIFO
  AudioOutputOptions audio;  ///< --rate, --format, --bits, --normalize, --loudness, --true-peak
  std::optional<double> duration;    ///< s; default: the file's, else until all have decayed
  std::string report;                ///< report path; default OUT.report.json (none for a stream)
  std::string spectrogram;           ///< also draw this PNG, if given
  acoustics::OscillatorModel model;
};

CLI::App* addSynthCommand(CLI::App& app, SynthOptions& options);

/// Sound besides the bubbles' (`run`'s solids): stems by name, each one vector per channel [Pa],
/// in the bubbles' channel order, and what made them for the report.
struct ExtraStems {
  std::vector<std::string> names;
  std::vector<std::vector<std::vector<float>>> stems;
  nlohmann::ordered_json report = nlohmann::ordered_json::object();
};

/// How renderSynth mixes other sound with the bubbles': `render` is called after the bubbles' render
/// with its length [samples] and rate [Hz]; the audio written is the sum of all stems, and each
/// stem — `bubbles` first — is written to stemFolder/NAME.wav (32-bit float WAV) scaled by the
/// same gain as the audio, so that the stems sum to it (exactly for a 32-bit float output, up to
/// dither and quantisation for PCM).
struct MixedSources {
  std::function<ExtraStems(std::size_t frames, double sampleRate)> render;
  std::filesystem::path stemFolder;
};

/// @brief The synth stage: renders `tracks` (`run`'s, in memory after its transfer stage; null:
///        read from options.input) with acoustics::synthesize and writes the audio, the
///        spectrogram and the report together.
/// @return the report's document (also when no report file is written)
/// @throws io::InputError, io::OutputError, CLI::ValidationError; io::Interrupted after a signal
///         (nothing written)
nlohmann::ordered_json renderSynth(const SynthOptions& options,
                                   const acoustics::BubbleTrackSet* tracks = nullptr,
                                   const MixedSources* mixed = nullptr);

/// @throws io::InputError, io::OutputError (main turns them into one-line errors)
int runSynthCommand(const SynthOptions& options);

}  // namespace fluidsound::tools
