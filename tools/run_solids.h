// tools/run_solids.h — `run`'s solids (docs/solids.md, "Bodies in run"): the contact log that
// simulate left (contacts.bin), each body's modes (cached in OUTDIR/modes), and the stems
// impacts, rolling and friction that acoustics::renderSolidSound makes of them at the scene's
// listeners, for the synth stage to mix with the bubbles (tools/synth_command.h, MixedSources).
#pragma once

#include <cstddef>
#include <array>
#include <filesystem>
#include <vector>

#include "acoustics/binaural/hrir_table.h"
#include "acoustics/modal/solid_sound.h"
#include "sim/core/contact_record.h"
#include "sim/scene.h"
#include "tools/synth_command.h"

namespace fluidsound::tools {

/// @brief OUTDIR/contacts.bin, checked to be the scene's (one body per scene body).
/// @throws io::InputError for a log that is missing, damaged or another scene's
sim::ContactLog readRunContactLog(const sim::Scene& scene, const std::filesystem::path& out);

/// One position per output channel [m], in the bubbles' order: a listener's, a head's centre twice.
std::vector<std::array<double, 3>> channelPositions(const sim::Scene& scene);

/// A head's ears: each of the three stems (impacts, rolling, friction) at its left and right ear.
struct HeadStems {
  std::array<std::vector<float>, 3> left, right;
};

/// @brief What a head `listener` hears of the solids: each sounding body rendered alone at the
///        head's centre and convolved with `table`'s pair of the measured direction nearest the
///        body (a static body's centre, a moving one's place at its first contact), as the bubbles
///        are (docs/binaural.md). `settings` as for the plain listeners (its listeners unused).
HeadStems hearWithHead(const sim::Scene& scene, const sim::ContactLog& log,
                       const std::vector<acoustics::SoundingBody>& bodies, const acoustics::SolidSoundSettings& settings,
                       const sim::Listener& listener, const acoustics::HrirTable& table);

/// @brief The solids' stems of the run in `out`, `frames` samples at `sampleRate` [Hz], one channel
///        per listener and two per head (hearWithHead).
/// @param scene  as read (its body meshes are loaded here)
/// @throws io::InputError for a contact log that is missing, damaged or not the scene's;
///         io::Interrupted after a signal
ExtraStems renderRunSolids(const sim::Scene& scene, const std::filesystem::path& out, std::size_t frames,
                           double sampleRate, bool quiet);

}  // namespace fluidsound::tools
