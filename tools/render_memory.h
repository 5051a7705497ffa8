// tools/render_memory.h — refuses, before the render, audio that cannot be held: duration × sample
// rate × channels above io::kMaxRenderSamples or above this machine's memory (io/render_limits.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/synthesis/synthesizer.h"
#include "sim/scene.h"

namespace fluidsound::tools {

/// @brief `synth`: throws when the render of `tracks` would be too large, naming what sets its
///        length: `--duration` (CLI::ValidationError, exit 2), else the file's `duration`, else the
///        bubble whose ring-down ends last (io::InputError naming `inputFile`, exit 3).
/// @param settings        what synth renders with (rate, duration if any, model)
/// @param durationOption  `--duration` [s], if given
/// @param availableBytes  physical memory [B]; 0 (unknown) checks the fixed limit only
void requireMemoryForRender(const acoustics::BubbleTrackSet& tracks, const std::string& inputFile,
                            const acoustics::SynthesisSettings& settings,
                            const std::optional<double>& durationOption,
                            std::uint64_t availableBytes);

/// @brief `run`: throws io::InputError naming `sceneFile` and `time.duration` when the scene's
///        audio (duration × audio.sample_rate × listeners) would not fit in `availableBytes`.
void requireMemoryForRender(const sim::Scene& scene, const std::string& sceneFile,
                            std::uint64_t availableBytes);

}  // namespace fluidsound::tools
