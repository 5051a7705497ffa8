// acoustics/synthesis/synthesis_stage.cpp — see synthesis_stage.h.
#include "acoustics/synthesis/synthesis_stage.h"

#include <chrono>
#include <cmath>
#include <string>
#include <utility>

namespace fluidsound::acoustics {

SynthesisSettings synthesisSettings(const BubbleTrackSet& tracks, const SynthesisOptions& options) {
  SynthesisSettings settings;
  settings.sampleRate = options.sampleRate.value_or(tracks.sampleRate);
  settings.duration = options.duration ? options.duration : tracks.duration;
  settings.model = options.model;
  settings.kernel = options.kernel;
  return settings;
}

SynthesisStageResult synthesize(const BubbleTrackSet& tracks, const SynthesisOptions& options,
                                StageObserver& observer) {
  const auto start = std::chrono::steady_clock::now();
  SynthesisStageResult result;
  result.settings = synthesisSettings(tracks, options);
  observer.started(result.settings.duration.value_or(0.0));
  SynthesisResult rendered = synthesize(tracks, result.settings, [&observer](double fraction) {
    if (observer.wasInterrupted())
      throw StageInterrupted("synth, " + std::to_string(std::lround(fraction * 100)) +
                             " % rendered");
    observer.progress(fraction);
  });
  result.channels = std::move(rendered.channels);
  result.report = rendered.report;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace fluidsound::acoustics
