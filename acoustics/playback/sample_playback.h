// acoustics/playback/sample_playback.h — recorded collision sounds played at the contacts' times:
// impacts as one-shots, slides and rolls as 1 s loops that play while their contact rubs, each
// with the gain of the loudness model (collision_loudness.h). The sample-playback paper's method
// (shared solids.md §1.4), plus what it leaves out: a per-pair minimum time between impacts and
// short fades where a loop starts and stops (docs/solids.md, Sample playback).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace fluidsound::acoustics {

/// A recorded sound, mono, at the output's sample rate.
struct RecordedSound {
  std::vector<float> samples;
  double sampleRate = 48000.0;  ///< [Hz]
};

/// One impact to play.
struct ImpactTrigger {
  double time = 0.0;    ///< [s]
  double gainDb = 0.0;  ///< ≤ 0 (impactGainDb)
};

/// @brief The impacts of one pair of bodies played into `samples` samples: each the recording
///        from its time, scaled by 10^(gain/20); an impact within `minimumInterval` [s] of the
///        last one played is dropped unless louder than it (Bullet can report one bounce over
///        two substeps; the paper retriggers on every contact).
std::vector<float> playImpacts(const RecordedSound& sound, std::span<const ImpactTrigger> impacts, std::size_t samples,
                               double minimumInterval = 0.01);

/// One substep of a loop's contact.
struct LoopSubstep {
  double time = 0.0;     ///< end of the substep [s]
  bool active = false;   ///< above the threshold (PlaybackThresholds): the loop plays
  double gainDb = 0.0;   ///< rubbingGainDb while active
};

/// @brief A slide's or roll's loop over consecutive substeps of length `substep` [s]: the
///        recording looped from its start where the contact becomes active, its gain linear
///        between the substeps' values, faded in and out over `fade` [s] where it starts and
///        stops (no click), silent while inactive.
std::vector<float> playLoop(const RecordedSound& sound, std::span<const LoopSubstep> substeps, double substep,
                            std::size_t samples, double fade = 0.005);

}  // namespace fluidsound::acoustics
