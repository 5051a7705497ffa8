// acoustics/bubble/bubble_track.h — the bubble tracks of `fluidsound.bubbles/1` as value types: the output
// of the transfer stage and the input of synthesis (format in docs/bubbles-format.md).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "sim/core/vec3.h"

namespace fluidsound::acoustics {

/// Upper bound on listeners (output channels, TrackSample::transfer values): the synthesizer
/// renders at most this many in one call (acoustics/synthesis/oscillator_bank.h), so a scene or a
/// bubbles file with more is refused when it is read.
inline constexpr int kMaxListeners = 16;

/// One per-frame sample of a bubble's track.
struct TrackSample {
  double time = 0.0;              ///< t [s]
  double depth = 0.0;             ///< h [m], bubble centre to the free surface, > radius
  std::vector<double> transfer;   ///< per listener: listener pressure ÷ free-field pressure at 1 m [-]
  std::optional<Vec3> position;  ///< bubble centre [m], world space, if known
  bool operator==(const TrackSample&) const = default;
};

/// One bubble: its size, birth and (optionally) its per-frame track.
struct BubbleTrack {
  double radius = 0.0;               ///< R [m], > 0
  double birth = 0.0;                ///< birth time [s], ≥ 0
  std::optional<double> amplitude;   ///< free-field pressure amplitude at 1 m [Pa]; else from the excitation model
  std::vector<TrackSample> track;    ///< in time order; empty: deep in open water, transfer 1
  bool operator==(const BubbleTrack&) const = default;
};

/// A whole `fluidsound.bubbles/1` document.
struct BubbleTrackSet {
  double sampleRate = 48000.0;          ///< Hz
  std::optional<double> duration;       ///< s; default: until the last bubble has decayed by 90 dB
  std::vector<std::string> listeners;   ///< one output channel each; empty: one channel
  std::vector<BubbleTrack> bubbles;
  bool operator==(const BubbleTrackSet&) const = default;

  /// Number of output channels: listeners.size(), at least 1.
  std::size_t channelCount() const { return listeners.empty() ? 1 : listeners.size(); }
};

}  // namespace fluidsound::acoustics
