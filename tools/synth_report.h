// tools/synth_report.h — what synth.report.json (OUT.report.json) says of a render (docs/cli.md):
// written by `synth` and by `run`'s synth stage, whose summary in report.json quotes it.
#pragma once

#include <cstddef>

#include "acoustics/synthesis/synthesis_stage.h"
#include "io/audio_file.h"
#include "tools/run_report.h"
#include "tools/synth_command.h"

namespace fluidsound::tools {

/// One render and the file it became.
struct SynthRender {
  const acoustics::SynthesisStageResult& stage;  ///< its channels may have moved to the file
  std::size_t channels = 0;                      ///< of the audio written
  std::size_t bubblesInFile = 0;                 ///< tracks the stage was given
  const io::AudioWriteSettings& write;
  const io::AudioWriteReport& written;
};

/// The settings (input, output, sample rate, oscillator model) and results (bubble counts, length,
/// peak, kernel, gain, the audio written: reportAudioOutput) of a render; stage times are added by
/// the caller.
void addSynthResults(RunReport& report, const SynthOptions& options, const SynthRender& render);

}  // namespace fluidsound::tools
