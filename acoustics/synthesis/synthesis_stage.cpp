// acoustics/synthesis/synthesis_stage.cpp — see synthesis_stage.h.
#include "acoustics/synthesis/synthesis_stage.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <stdexcept>
#include <utility>

#include "acoustics/synthesis/head_render.h"

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
  if (!tracks.heads.empty() && options.headResponses == nullptr)  // before the render, not after
    throw std::invalid_argument("synthesize: the tracks have heads but no head responses were given");
  observer.started(result.settings.duration.value_or(0.0));
  SynthesisResult rendered = synthesize(tracks, result.settings, [&observer](double fraction) {
    if (observer.wasInterrupted())
      throw StageInterrupted("synth, " + std::to_string(std::lround(fraction * 100)) +
                             " % rendered");
    observer.progress(fraction);
  });
  result.report = rendered.report;
  if (tracks.heads.empty()) {
    result.channels = std::move(rendered.channels);
  } else {
    for (std::size_t l = 0; l < rendered.channels.size(); ++l) {
      const ListenerHead* head = l < tracks.listeners.size() ? tracks.head(tracks.listeners[l]) : nullptr;
      if (head == nullptr) {
        result.channels.push_back(std::move(rendered.channels[l]));
        continue;
      }
      if (observer.wasInterrupted()) throw StageInterrupted("synth, rendering head " + head->listener);
      HeadSignals ears = renderHead(tracks, l, *head, *options.headResponses, result.settings,
                                    result.report.frames);
      result.headDirections += ears.directions;
      result.channels.push_back(std::move(ears.left));
      result.channels.push_back(std::move(ears.right));
    }
    result.report.peakPascals = 0.0;  // of what is written: the ears replace the heads' centres
    for (const std::vector<float>& channel : result.channels)
      for (float x : channel) result.report.peakPascals = std::max(result.report.peakPascals, static_cast<double>(std::fabs(x)));
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace fluidsound::acoustics
