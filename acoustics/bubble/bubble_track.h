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

/// The free ring of a resonator between a bubble and the listeners (a vessel's air column): what
/// the resonator goes on sounding at its own frequency after the bubble's onset, beside the
/// bubble's own sound that the transfer weights (docs/transfer.md, "The air column's ring").
/// For listener l: A·gain_l·e^{−β_r τ}·cos(2πf τ + phase_l), τ = t − birth ≥ 0, A the bubble's
/// free-field amplitude at 1 m.
struct ResonatorRing {
  double frequency = 0.0;     ///< f [Hz]
  double decayRate = 0.0;     ///< β_r [1/s]
  std::vector<double> gain;   ///< per listener [-]
  std::vector<double> phase;  ///< per listener [rad]
  bool operator==(const ResonatorRing&) const = default;
};

/// One bubble: its size, birth and (optionally) its per-frame track.
struct BubbleTrack {
  double radius = 0.0;               ///< R [m], > 0
  double birth = 0.0;                ///< birth time [s], ≥ 0
  std::optional<double> amplitude;   ///< free-field pressure amplitude at 1 m [Pa]; else from the excitation model
  std::vector<TrackSample> track;    ///< in time order; empty: deep in open water, transfer 1
  std::vector<ResonatorRing> rings;  ///< the transfer stage's, one per resonance it found
  bool operator==(const BubbleTrack&) const = default;
};

/// A listener that is a head (docs/binaural.md): its channel becomes two, the left and the right
/// ear, each the pressure at the head's centre filtered by the head-related impulse response of
/// the bubble's direction. The transfer values stay those of the head's centre.
struct ListenerHead {
  std::string listener;  ///< the listener's name (one of BubbleTrackSet::listeners)
  Vec3 position{};       ///< head centre [m]
  Vec3 facing{};         ///< where the nose points (any length > 0)
  Vec3 up{};             ///< the top of the head (any length > 0, not parallel to facing)
  bool operator==(const ListenerHead&) const = default;
};

/// Whether `facing` and `up` orient a head: both non-zero and not parallel (the sine of the angle
/// between them above 10⁻³, so that the ears' axis up × facing is well defined).
inline bool isHeadOrientation(const Vec3& facing, const Vec3& up) {
  const Vec3 c{facing[1] * up[2] - facing[2] * up[1], facing[2] * up[0] - facing[0] * up[2],
               facing[0] * up[1] - facing[1] * up[0]};
  const auto square = [](const Vec3& v) { return v[0] * v[0] + v[1] * v[1] + v[2] * v[2]; };
  return square(facing) > 0.0 && square(up) > 0.0 && square(c) > 1e-6 * square(facing) * square(up);
}

/// A whole `fluidsound.bubbles/1` document.
struct BubbleTrackSet {
  double sampleRate = 48000.0;          ///< Hz
  std::optional<double> duration;       ///< s; default: until the last bubble has decayed by 90 dB
  std::vector<std::string> listeners;   ///< one output channel each; empty: one channel
  std::vector<BubbleTrack> bubbles;
  std::vector<ListenerHead> heads;      ///< the listeners that are heads (two output channels)
  std::optional<std::string> hrtf;      ///< SOFA file of the heads' responses; default MIT KEMAR
  bool operator==(const BubbleTrackSet&) const = default;

  /// Number of listeners (transfer values per track sample): listeners.size(), at least 1.
  std::size_t channelCount() const { return listeners.empty() ? 1 : listeners.size(); }
  /// The head of listener `name`, or nullptr for a point listener.
  const ListenerHead* head(const std::string& name) const {
    for (const ListenerHead& h : heads)
      if (h.listener == name) return &h;
    return nullptr;
  }
};

/// Suffixes of a head's two output channels, after its listener's name.
inline constexpr const char* kLeftEarSuffix = ".left";
inline constexpr const char* kRightEarSuffix = ".right";

/// @brief The listener (index into set.listeners) of each rendered channel, in order: a head's
///        two ears both give its listener; {0} for a set without listeners.
inline std::vector<std::size_t> outputChannelListeners(const BubbleTrackSet& set) {
  if (set.listeners.empty()) return {0};
  std::vector<std::size_t> out;
  for (std::size_t l = 0; l < set.listeners.size(); ++l) {
    out.push_back(l);
    if (set.head(set.listeners[l]) != nullptr) out.push_back(l);
  }
  return out;
}

/// @brief The names of the rendered audio's channels, in order: each listener's name, or for a
///        head its name + ".left" and + ".right"; none for a set without listeners (one
///        unnamed channel).
inline std::vector<std::string> outputChannelNames(const BubbleTrackSet& set) {
  std::vector<std::string> names;
  for (const std::string& l : set.listeners) {
    if (set.head(l) != nullptr) {
      names.push_back(l + kLeftEarSuffix);
      names.push_back(l + kRightEarSuffix);
    } else {
      names.push_back(l);
    }
  }
  return names;
}

}  // namespace fluidsound::acoustics
