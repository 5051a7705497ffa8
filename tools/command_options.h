// tools/command_options.h — the options every subcommand shares, and the physics-model options of
// the commands that render bubbles. Kept free of CLI11 templates (forward declaration only).
#pragma once

#include <initializer_list>
#include <string>

#include "acoustics/bubble/oscillator_model.h"
#include "io/audio_file.h"

namespace CLI {
class App;
}

namespace fluidsound::tools {

/// Options of every subcommand.
struct CommonOptions {
  int threads = 0;     ///< worker threads; 0 = all cores
  bool quiet = false;  ///< no progress, no notes
};

/// Adds --threads and --quiet to a subcommand.
void addCommonOptions(CLI::App& command, CommonOptions& options);

/// Adds the oscillator-model switches (--thermal, --vapour, --hydrostatic, --damping,
/// --excitation, --chirp) to a subcommand; defaults are those of docs/physics.md.
void addOscillatorModelOptions(CLI::App& command, acoustics::OscillatorModel& model);

/// Every field of `model` as text, for the input fingerprint of the stages that use it (`run`
/// runs transfer and synth again when the model changes).
std::string oscillatorModelFingerprint(const acoustics::OscillatorModel& model);

/// A file named on the command line, with the option (or argument) that names it.
struct NamedFile {
  const char* option;  ///< e.g. "--report", or "bubbles" for a positional argument
  std::string path;    ///< empty: not given (skipped)
  bool input = false;  ///< `-` as an input is standard input, never the same as `-` as an output
};

/// @brief Before any work: no two of `files` may be the same file. Existing files are compared
///        with std::filesystem::equivalent (links, `..` and hard links included), new names by
///        their normalised absolute path.
/// @throws CLI::ValidationError (exit 2) naming both options and the file
void requireDistinctFiles(std::initializer_list<NamedFile> files);

/// The audio format and sample size a command writes.
struct AudioLayout {
  io::AudioFormat format = io::AudioFormat::Wav;
  int bits = 32;  ///< 32 = float (WAV only), 24 or 16 = PCM
};

/// @brief The audio format of `output`: `--format` if given (it must agree with a .wav or .flac
///        extension), else the extension; `-`, a character device and a FIFO default to WAV. With
///        `bits` (0 = the format's default: 32 for WAV, 24 for FLAC) checked against the format.
/// @throws CLI::ValidationError (exit 2) naming --output, --format or --bits
AudioLayout audioLayout(const std::string& output, const std::string& format, int bits);

/// Exit codes of the CLI (docs/cli.md).
enum ExitCode : int {
  kExitSuccess = 0,
  kExitValidationFailed = 1,  ///< `validate` found a row outside its tolerance
  kExitUsage = 2,             ///< bad command line
  kExitBadInput = 3,          ///< an input file is missing or invalid
  kExitOutputFailed = 4,      ///< an output could not be written
  kExitInternal = 5,          ///< anything else (a bug)
  kExitSimulationFailed = 6,  ///< the liquid solver blew up (a velocity not finite)
};

}  // namespace fluidsound::tools
