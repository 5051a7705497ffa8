// tools/command_options.cpp — shared subcommand options (see command_options.h).
#include "tools/command_options.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <system_error>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/output_file.h"
#include "tools/number_checks.h"

namespace fluidsound::tools {

void addCommonOptions(CLI::App& command, CommonOptions& options) {
  command.add_option("--threads", options.threads, "worker threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  command.add_flag("--quiet,-q", options.quiet, "no progress display and no notes");
}

void addOscillatorModelOptions(CLI::App& command, acoustics::OscillatorModel& model) {
  using namespace acoustics;
  const std::map<std::string, DampingModel> damping{{"devin", DampingModel::Devin},
                                                    {"vandendoel", DampingModel::VanDenDoel}};
  const std::map<std::string, ExcitationModel> excitation{
      {"jet", ExcitationModel::NeckCollapseJet},
      {"displacement", ExcitationModel::InitialDisplacement}};
  command.add_flag_callback(
      "--thermal", [&model] { model.polytropic = PolytropicModel::Thermal; },
      "thermal effective polytropic index (Prosperetti) instead of adiabatic");
  command.add_flag("--vapour", model.vapour, "include the vapour pressure in the restoring term");
  command.add_flag("--hydrostatic", model.hydrostatic, "ambient pressure p0 + rho g h at the bubble's depth");
  command.add_option("--damping", model.damping, "damping model: devin (default) or vandendoel")
      ->transform(CLI::CheckedTransformer(damping, CLI::ignore_case));
  command.add_option("--excitation", model.excitation, "excitation: jet (default) or displacement")
      ->transform(CLI::CheckedTransformer(excitation, CLI::ignore_case));
  command.add_option("--displacement", model.initialDisplacement,
                     "initial radial displacement epsilon for --excitation displacement")
      ->check(finitePositive());
  command.add_flag("--chirp", model.chirp, "van den Doel rising pitch f0 (1 + xi beta t)");
  command.add_option("--chirp-rise", model.chirpRiseFactor, "van den Doel rise factor xi (default 0.1)")
      ->check(finiteNonNegative());
}

std::string oscillatorModelFingerprint(const acoustics::OscillatorModel& m) {
  char text[512];
  std::snprintf(
      text, sizeof text,
      "model polytropic %d surface-tension %d vapour %d hydrostatic %d damping %d excitation %d "
      "displacement %.17g jet-cone %.17g jet-max %.17g chirp %d chirp-rise %.17g",
      static_cast<int>(m.polytropic), m.surfaceTension, m.vapour, m.hydrostatic,
      static_cast<int>(m.damping), static_cast<int>(m.excitation), m.initialDisplacement,
      m.jetConeParameter, m.jetMaxDuration, m.chirp, m.chirpRiseFactor);
  return text;
}

namespace {

namespace fs = std::filesystem;

/// The same file: both exist and are one file, or their normalised absolute paths agree.
bool sameFile(const NamedFile& a, const NamedFile& b) {
  const bool aStdio = a.path == "-", bStdio = b.path == "-";
  if (aStdio || bStdio) return aStdio && bStdio && a.input == b.input;
  std::error_code ec;
  if (fs::exists(a.path, ec) && fs::exists(b.path, ec)) return fs::equivalent(a.path, b.path, ec);
  const fs::path left = fs::weakly_canonical(fs::absolute(a.path, ec), ec);
  const fs::path right = fs::weakly_canonical(fs::absolute(b.path, ec), ec);
  return left.lexically_normal() == right.lexically_normal();
}

}  // namespace

void requireDistinctFiles(std::initializer_list<NamedFile> files) {
  const std::vector<NamedFile> given(files);
  for (std::size_t i = 0; i < given.size(); ++i) {
    for (std::size_t j = i + 1; j < given.size(); ++j) {
      if (given[i].path.empty() || given[j].path.empty() || !sameFile(given[i], given[j])) continue;
      const std::string options = std::string(given[i].option) + " and " + given[j].option;
      throw CLI::ValidationError(
          options, "both name " + given[j].path + "; an output must be neither an input nor another output");
    }
  }
}

AudioLayout audioLayout(const std::string& output, const std::string& format, int bits) {
  AudioLayout layout;
  if (!format.empty()) {
    std::string name = format;
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    layout.format = name == "flac" ? io::AudioFormat::Flac : io::AudioFormat::Wav;
    const auto fromName = io::audioFormatFromPath(output);
    if (fromName && *fromName != layout.format)
      throw CLI::ValidationError("--format and --output",
                                 "--format " + format + " but " + output + " names the other format");
  } else if (const auto fromName = io::audioFormatFromPath(output)) {
    layout.format = *fromName;
  } else if (io::resolveOutput(output).kind == io::OutputKind::Replace) {
    // A stream (`-`, a device, a FIFO) has no extension and gets WAV; a file name must say.
    const std::string expected = "expected a name ending in .wav or .flac, or --format wav|flac";
    throw CLI::ValidationError("--output", output + ": no audio format for this name: " + expected);
  }
  const bool flac = layout.format == io::AudioFormat::Flac;
  layout.bits = bits != 0 ? bits : (flac ? 24 : 32);
  if (flac && layout.bits == 32)
    throw CLI::ValidationError("--bits", "FLAC holds 16- or 24-bit PCM, not 32-bit float: use --bits 24 or 16");
  return layout;
}

}  // namespace fluidsound::tools
