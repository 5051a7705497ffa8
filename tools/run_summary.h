// tools/run_summary.h — the parts of report.json's `run` object that summarise the stages'
// results (docs/cli.md, `run`): the bubbles' sizes, the synth report's levels, and the rendered
// spectrum against the one the bubble tracks predict.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "acoustics/bubble/bubble_track.h"

namespace fluidsound::tools {

/// Bubble counts by radius, 10 log-spaced bins from 0.1 to 10 mm (radii outside go to the ends).
nlohmann::ordered_json radiusHistogram(const acoustics::BubbleTrackSet& tracks);

/// @brief Copies the synth report's peak (Pa and dBFS), oscillator kernel and audio output
///        (scale, gain, loudness, names) into `run`, those of them the report has.
void addSynthSummary(nlohmann::ordered_json& run, const nlohmann::ordered_json& synthReport);

/// @brief Per listener, the spectral centroid of the audio file and the one predicted from the
///        bubble tracks (acoustics/analysis/centroid_prediction.h, docs/synthesis.md "What the
///        spectrum shows"); null where a channel has no energy in the band.
/// @param sampleRate  run's --rate, if given (the synth stage's rate; else the tracks')
nlohmann::ordered_json spectrumSummary(const acoustics::BubbleTrackSet& tracks,
                                       const std::filesystem::path& audioPath,
                                       const std::optional<double>& sampleRate);

}  // namespace fluidsound::tools
