// acoustics/playback/collision_playback.h — the sample-playback baseline as a stage: the contact
// log of a run (sim/core/contact_record.h) played as recorded collision sounds, per pair of bodies
// its impacts as one-shots and its slides and rolls as loops (sample_playback.h), each with the
// gain of the oscillator loudness model (collision_loudness.h) relative to the pair's loudest
// event, spread as 1/r from the contact to each listener with the delay r/c; three stems like the
// modal stage's (docs/solids.md, "Sample playback in run").
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "acoustics/playback/sample_playback.h"
#include "sim/core/contact_record.h"

namespace fluidsound::acoustics {

/// The recordings of one pair of materials; an empty one plays nothing.
struct CollisionRecordings {
  RecordedSound impact, slide, roll;
  /// The pressure [Pa] a full-scale sample stands for, 1 m from the contact, at the pair's loudest
  /// event in the log (each recording normalised to its pair's loudest, as the paper's are).
  double peakPascals = 1.0;
};

struct CollisionPlaybackSettings {
  double sampleRate = 48000.0;             ///< [Hz]; the recordings' too
  std::size_t samples = 0;                 ///< length of each stem
  std::vector<std::array<double, 3>> listeners;  ///< one per output channel, world [m]
  double soundSpeed = 343.2;               ///< c [m/s] (air, 20 °C)
  /// The paper's thresholds (shared solids.md T9): an impact closes faster than this [m/s]; a
  /// slide plays while its friction force is at least this [N].
  double impactSpeed = 0.02, slideForce = 1.0;
  /// A roll plays while it rolls (rolling speed above sliding speed) faster than this [rad/s]: the
  /// paper's rolling torque M_t ≥ 1e-3 N·m is not in the log (a choice: docs/solids.md).
  double rollRate = 1.0;
  double nearest = 0.1;  ///< the 1/r law is held below this distance [m]
};

/// The three stems, each one vector per listener channel [Pa].
struct PlaybackStems {
  std::vector<std::vector<float>> impacts, rolling, friction;
  std::size_t impactsPlayed = 0, slideSubsteps = 0, rollSubsteps = 0;
};

/// @brief Plays the contacts of `log`.
/// @param recordingsOf  the recordings of the pair (body index, body index or wall −1 … −6), or
///        null: that pair is silent
/// @throws std::invalid_argument for settings out of range or a recording at another sample rate
/// @note Deterministic: pairs in ascending order, one thread.
PlaybackStems renderCollisionPlayback(const sim::ContactLog& log,
                                      const std::function<const CollisionRecordings*(int, int)>& recordingsOf,
                                      const CollisionPlaybackSettings& settings);

}  // namespace fluidsound::acoustics
