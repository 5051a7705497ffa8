// tools/run_solids.h — `run`'s solids (docs/solids.md, "Bodies in run"): the contact log that
// simulate left (contacts.bin), each body's modes (cached in OUTDIR/modes), and the stems
// impacts, rolling and friction that acoustics::renderSolidSound makes of them at the scene's
// listeners, for the synth stage to mix with the bubbles (tools/synth_command.h, MixedSources).
#pragma once

#include <cstddef>
#include <array>
#include <filesystem>
#include <vector>

#include "sim/core/contact_record.h"
#include "sim/scene.h"
#include "tools/synth_command.h"

namespace fluidsound::tools {

/// @brief OUTDIR/contacts.bin, checked to be the scene's (one body per scene body).
/// @throws io::InputError for a log that is missing, damaged or another scene's
sim::ContactLog readRunContactLog(const sim::Scene& scene, const std::filesystem::path& out);

/// One position per output channel [m], in the bubbles' order: a listener's, a head's centre twice.
std::vector<std::array<double, 3>> channelPositions(const sim::Scene& scene);

/// @brief The solids' stems of the run in `out`, `frames` samples at `sampleRate` [Hz], one channel
///        per listener and two per head (both heard at the head's centre: the solids are not
///        rendered through the HRTF).
/// @param scene  as read (its body meshes are loaded here)
/// @throws io::InputError for a contact log that is missing, damaged or not the scene's;
///         io::Interrupted after a signal
ExtraStems renderRunSolids(const sim::Scene& scene, const std::filesystem::path& out, std::size_t frames,
                           double sampleRate, bool quiet);

}  // namespace fluidsound::tools
