// io/bubble_track_limits.h — the ranges of the numbers in a `fluidsound.bubbles/1` file
// (docs/bubbles-format.md, "Ranges"), shared by the validating reader and the one-pass reader so
// that both accept exactly the same documents. Each bound is physically generous: a value outside
// it is a typo or garbage, and would otherwise overflow a sample index or underflow to a
// denormal inside the synthesizer.
#pragma once

#include <cmath>
#include <cstdint>

namespace fluidsound::io {

/// Output sample rates [Hz]: the range of `synth --rate` and of a scene's `audio.sample_rate`.
inline constexpr std::uint64_t kMinTrackSampleRate = 8000;
inline constexpr std::uint64_t kMaxTrackSampleRate = 768000;

/// Bubble radius [m]: 1 µm rings at about 3 MHz (far above any audio rate), 1 m at about 3 Hz
/// (Minnaert); entrained bubbles are 0.1–10 mm.
inline constexpr double kMinBubbleRadius = 1e-6;
inline constexpr double kMaxBubbleRadius = 1.0;

/// Excitation amplitude [Pa at 1 m]: from far below the threshold of hearing (20 µPa) to one
/// atmosphere (101 325 Pa), beyond which a sound wave in water is no longer linear.
inline constexpr double kMinBubbleAmplitude = 1e-9;
inline constexpr double kMaxBubbleAmplitude = 1e5;

/// Times [s]: `duration`, `birth` and track `t`; 10⁶ s is 11.6 days of audio.
inline constexpr double kMaxTrackTime = 1e6;

/// Depth below the free surface [m]: the deepest ocean is about 11 km.
inline constexpr double kMaxBubbleDepth = 11000.0;

/// |transfer| (pressure ratio): a listener 1 µm from a bubble hears 10⁶ times its 1 m pressure.
inline constexpr double kMaxTransfer = 1e6;

/// |position| per coordinate [m].
inline constexpr double kMaxTrackCoordinate = 1e6;

/// A sample rate the file may give: a whole number of Hz in the range above.
inline bool isTrackSampleRate(double hz) {
  return hz >= static_cast<double>(kMinTrackSampleRate) &&
         hz <= static_cast<double>(kMaxTrackSampleRate) && hz == std::floor(hz);
}
inline bool isBubbleRadius(double r) { return r >= kMinBubbleRadius && r <= kMaxBubbleRadius; }
inline bool isBubbleAmplitude(double a) {
  return a >= kMinBubbleAmplitude && a <= kMaxBubbleAmplitude;
}
/// `duration`: > 0 and at most kMaxTrackTime.
inline bool isTrackDuration(double s) { return s > 0.0 && s <= kMaxTrackTime; }
/// `birth` and `t`: 0 … kMaxTrackTime.
inline bool isTrackTime(double s) { return s >= 0.0 && s <= kMaxTrackTime; }
/// `depth`, given the bubble's radius: > radius and at most kMaxBubbleDepth.
inline bool isBubbleDepth(double depth, double radius) {
  return depth > radius && depth <= kMaxBubbleDepth;
}
inline bool isTransfer(double v) { return std::fabs(v) <= kMaxTransfer; }
inline bool isTrackCoordinate(double x) { return std::fabs(x) <= kMaxTrackCoordinate; }

}  // namespace fluidsound::io
