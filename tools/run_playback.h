// tools/run_playback.h — `run --solids samples` (docs/solids.md, "Sample playback in run"): the
// scene's collision_samples read and checked, and the contact log played back with them
// (acoustics::renderCollisionPlayback) as the stems impacts, rolling and friction.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "acoustics/playback/collision_playback.h"
#include "sim/scene.h"
#include "tools/synth_command.h"

namespace fluidsound::tools {

/// @brief Reads every recording of the scene's collision_samples (mixed down to mono).
/// @throws io::InputError naming the scene file, the field (`collision_samples[1].slide`) and the
///         recording's own problem: missing, not audio, empty, or not at the scene's sample rate
std::vector<acoustics::CollisionRecordings> readCollisionRecordings(const sim::Scene& scene);

/// @brief The playback stems of the run in `out`, `frames` samples at `sampleRate` [Hz], one
///        channel per listener, two per head (both the recording at the head's centre: playback is
///        not rendered through the HRTF), as renderRunSolids's.
/// @throws io::InputError as readCollisionRecordings, or for a contact log that is not the scene's
ExtraStems renderRunPlayback(const sim::Scene& scene, const std::filesystem::path& out, std::size_t frames,
                             double sampleRate, bool quiet);

}  // namespace fluidsound::tools
