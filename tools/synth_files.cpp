// tools/synth_files.cpp — see synth_files.h.
#include "tools/synth_files.h"

#include <cstdio>
#include <filesystem>
#include <utility>

#include "acoustics/synthesis/oscillator_bank.h"
#include "io/bubble_track_file.h"
#include "io/hrir_file.h"
#include "io/input_error.h"
#include "io/spectrogram_image.h"
#include "io/text_file.h"
#include "tools/command_options.h"
#include "tools/spectrogram_picture.h"

namespace fluidsound::tools {

namespace {

/// OUT.report.json beside a file output (so out.wav and out.flac keep their own reports); none for
/// a stream (`-`, a device, a FIFO): a report there would land in /dev or mix with the audio.
std::string defaultReportPath(const std::string& output) {
  if (io::resolveOutput(output).kind != io::OutputKind::Replace) return {};
  return output + ".report.json";
}

}  // namespace

acoustics::BubbleTrackSet readSynthInput(const SynthOptions& o) {
  std::error_code sizeError;
  const auto inputBytes = std::filesystem::file_size(o.input, sizeError);
  constexpr std::uintmax_t kAnnounceReadBytes = 8u << 20;  // a read that takes about a second
  if (!sizeError && inputBytes > kAnnounceReadBytes && !o.common.quiet)
    std::fprintf(stderr, "fluidsound: note: reading %s (%ju MB)\n", o.input.c_str(),
                 inputBytes >> 20);
  acoustics::BubbleTrackSet tracks = io::readBubbleTracks(o.input);
  if (tracks.channelCount() > static_cast<std::size_t>(acoustics::kMaxListeners))
    throw io::InputError(o.input, "listeners",
                         "at most " + std::to_string(acoustics::kMaxListeners) + " listeners",
                         std::to_string(tracks.listeners.size()));
  return tracks;
}

acoustics::HrirTable readHeadResponses(const acoustics::BubbleTrackSet& tracks, const std::string& input,
                                       double sampleRate) {
  std::filesystem::path sofa = io::defaultHrirFile();
  if (tracks.hrtf) {
    sofa = *tracks.hrtf;
    if (sofa.is_relative() && input != io::kStandardInput) sofa = std::filesystem::path(input).parent_path() / sofa;
  }
  try {
    return io::readHrirTable(sofa, sampleRate);
  } catch (const io::InputError& error) {
    throw io::InputError(input, "hrtf",
                         tracks.hrtf ? "a SOFA file of head-related impulse responses (relative to this file's folder)"
                                     : "the default HRTF set (Debian's libmysofa1, MIT KEMAR) for the heads",
                         error.what());
  }
}

std::string checkedSynthOutputs(const SynthOptions& o) {
  audioLayout(o.output, o.audio.format, o.audio.bits);  // the name, --format and --bits agree
  const std::string reportPath = o.report.empty() ? defaultReportPath(o.output) : o.report;
  requireDistinctFiles({{"bubbles", o.input, true},
                        {"--output", o.output},
                        {"--report", reportPath},
                        {"--spectrogram", o.spectrogram}});
  io::requireWritableFolder(o.output);
  if (!reportPath.empty()) io::requireWritableFolder(reportPath);
  if (!o.spectrogram.empty()) io::requireWritableFolder(o.spectrogram);
  return reportPath;
}

io::AudioWriteReport addSynthFiles(io::OutputBatch& outputs, const SynthOptions& o,
                                   const io::AudioBuffer& audio,
                                   const io::AudioWriteSettings& write) {
  io::EncodedAudio encoded = io::encodeAudio(o.output, audio, write);
  outputs.add(o.output, std::move(encoded.bytes));
  if (!o.spectrogram.empty()) {
    const std::string title = io::isStandardOutput(o.output)
                                  ? std::string("standard output")
                                  : std::filesystem::path(o.output).filename().string();
    outputs.add(o.spectrogram, spectrogramPicture(audio, {}, title));
  }
  return encoded.report;
}

}  // namespace fluidsound::tools
