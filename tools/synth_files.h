// tools/synth_files.h — the files of a synth render: the bubble file it reads, and those it writes
// (the audio, its spectrogram, the report), all checked before the render, all encoded in memory
// and then written together, so that a failure leaves none of them.
#pragma once

#include <string>

#include "acoustics/binaural/hrir_table.h"
#include "io/audio_file.h"
#include "io/output_file.h"
#include "tools/synth_command.h"

namespace fluidsound::tools {

/// @brief Reads options.input, with a note first when it takes about a second to read.
/// @throws io::InputError for a bad file or more than acoustics::kMaxListeners listeners
acoustics::BubbleTrackSet readSynthInput(const SynthOptions& options);

/// @brief The heads' impulse responses at `sampleRate` [Hz]: the tracks' `hrtf` file (relative
///        to `input`'s folder), else the default MIT KEMAR set.
/// @throws io::InputError naming `input`, its field `hrtf` and the SOFA file's own problem
acoustics::HrirTable readHeadResponses(const acoustics::BubbleTrackSet& tracks, const std::string& input,
                                       double sampleRate);

/// @brief Refuses, before the render, every output that cannot be written or names an input or
///        another output, and an audio name, --format and --bits that disagree (audioLayout()).
/// @return the report's path: --report, else OUT.report.json beside a file output; empty: no
///         report (a stream output, `-`, a device or a FIFO, without --report)
std::string checkedSynthOutputs(const SynthOptions& options);

/// @brief Encodes `audio` as options.output (and the spectrogram PNG, if asked for) into `outputs`.
/// @return what encoding did to the signal (gain, peak, clipping, loudness)
io::AudioWriteReport addSynthFiles(io::OutputBatch& outputs, const SynthOptions& options,
                                   const io::AudioBuffer& audio,
                                   const io::AudioWriteSettings& write);

}  // namespace fluidsound::tools
