// tools/spectrogram_command.cpp — `fluidsound spectrogram` (see spectrogram_command.h).
#include "tools/spectrogram_command.h"

#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "io/audio_file.h"
#include "io/output_file.h"
#include "io/spectrogram_image.h"
#include "io/text_file.h"
#include "tools/number_checks.h"
#include "tools/spectrogram_picture.h"

namespace fluidsound::tools {

CLI::App* addSpectrogramCommand(CLI::App& app, SpectrogramOptions& o) {
  CLI::App* c = app.add_subcommand("spectrogram", "draw the spectrogram of an audio file to a PNG");
  c->add_option("audio", o.input, "audio file (WAV, FLAC, anything libsndfile reads)")->required();
  c->add_option("-o,--output", o.output, "output PNG; - = standard output")->required();
  c->add_flag("--log-frequency", o.settings.logFrequency, "logarithmic frequency axis");
  c->add_option("--min-frequency", o.settings.minFrequency, "lower edge of a log axis, Hz")
      ->check(finitePositive());
  c->add_option("--window", o.settings.windowSamples, "FFT window length, samples")
      ->check(CLI::Range(64, 65536));
  c->add_option("--hop", o.settings.hopSamples, "step between windows, samples")->check(CLI::Range(1, 65536));
  c->add_option("--range", o.settings.dynamicRangeDb, "dynamic range of the colours, dB")
      ->check(finiteRange(10.0, 200.0));
  c->add_option("--width", o.settings.width, "image width, px")->check(CLI::Range(200, 10000));
  c->add_option("--height", o.settings.height, "image height, px")->check(CLI::Range(150, 10000));
  c->add_option("--channel", o.settings.channel, "channel to draw (0-based; default: mean of all)")
      ->check(CLI::NonNegativeNumber);
  addCommonOptions(*c, o.common);
  return c;
}

int runSpectrogramCommand(const SpectrogramOptions& o) {
  requireDistinctFiles({{"audio", o.input, true}, {"--output", o.output}});
  io::requireWritableFolder(o.output);
  const io::AudioBuffer audio = io::readAudio(o.input);
  io::writeOutputFile(o.output, spectrogramPicture(audio, o.settings, std::filesystem::path(o.input).filename().string()));
  if (!o.common.quiet)
    std::fprintf(stderr, "fluidsound: wrote %s\n",
                 io::isStandardOutput(o.output) ? "standard output" : o.output.c_str());
  return kExitSuccess;
}

}  // namespace fluidsound::tools
