// acoustics/synthesis/synthesis_stage.h — the synth stage as one library function: the settings a
// render uses (the caller's choices, else the bubble file's), the Synthesizer run on them
// (acoustics/synthesis/synthesizer.h) with progress and stop through a StageObserver, and what it
// did. The result is sound pressure [Pa] per listener: levels, normalisation and loudness targets
// are the audio file's full scale, so they belong to the file's encoding (io/audio_file.h), not to
// this stage. docs/synthesis.md.
#pragma once

#include <optional>
#include <vector>

#include "acoustics/binaural/hrir_table.h"
#include "acoustics/bubble/bubble_track.h"
#include "acoustics/bubble/oscillator_model.h"
#include "acoustics/synthesis/oscillator_kernel.h"
#include "acoustics/synthesis/synthesizer.h"
#include "sim/core/stage_observer.h"

namespace fluidsound::acoustics {

/// What the stage is asked for; what is not given comes from the bubble tracks.
struct SynthesisOptions {
  std::optional<double> sampleRate;  ///< Hz; default: the tracks' sample_rate
  std::optional<double> duration;    ///< s; default: the tracks' duration, else until all decayed
  OscillatorModel model;             ///< the run's one model (transfer's ω uses it too)
  std::optional<OscillatorKernel> kernel;  ///< inner loop; default: the fastest this CPU runs
  /// The heads' impulse responses at the render's rate (io::readHrirTable); required when the
  /// tracks have heads (docs/binaural.md), unused otherwise.
  const HrirTable* headResponses = nullptr;
};

/// The rendered sound and what the render did (the results of synth.report.json).
struct SynthesisStageResult {
  SynthesisSettings settings;                ///< what it rendered with
  /// Pressure [Pa] in the order of outputChannelNames(tracks): one per listener, two per head.
  std::vector<std::vector<float>> channels;
  SynthesisReport report;                    ///< of the render of every listener's channel
  std::size_t headDirections = 0;            ///< measured directions the heads heard bubbles from
  double seconds = 0.0;  ///< wall-clock time of the render [s]

  /// Length of the audio [s].
  double durationSeconds() const {
    return static_cast<double>(report.frames) / settings.sampleRate;
  }
  /// Oscillator samples rendered per wall-clock second (0 for an instant render).
  double oscillatorSamplesPerSecond() const {
    return seconds > 0 ? static_cast<double>(report.oscillatorSamples) / seconds : 0.0;
  }
};

/// The Synthesizer's settings for `options` on `tracks`: sample rate and duration from the
/// options, else from the tracks; the model and kernel of the options; water at 20 °C.
SynthesisSettings synthesisSettings(const BubbleTrackSet& tracks, const SynthesisOptions& options);

/// @brief Renders `tracks` (validated, at most kMaxListeners listeners) with
///        synthesisSettings(tracks, options). observer.started(seconds of audio, 0 when the
///        length is set by the last bubble's decay) first; then, between waves of the render,
///        observer.wasInterrupted() and observer.progress(fraction done). A point listener's
///        channel is the Synthesizer's, bit for bit; a head's two are renderHead's.
/// @throws StageInterrupted("synth, N % rendered") when the observer asks to stop;
///         std::invalid_argument if options.kernel names a kernel this CPU cannot run, or the
///         tracks have heads and options.headResponses is missing or at another rate
SynthesisStageResult synthesize(const BubbleTrackSet& tracks, const SynthesisOptions& options,
                                StageObserver& observer);

}  // namespace fluidsound::acoustics
