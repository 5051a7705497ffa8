// acoustics/track_interpolation.h — smooth interpolation of a bubble track's per-frame values
// (depth, transfer) to any time, for the synthesizer: monotone cubic Hermite (Fritsch & Butland
// 1984), so no overshoot (depth never crosses the clamp it was given, transfer never changes sign)
// and a continuous first derivative (no zipper noise from frame-rate corners).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "acoustics/bubble_track.h"

namespace fluidsound::acoustics {

/// Values of a track at one instant.
struct TrackValues {
  double depth = 0.0;            ///< h [m]
  std::vector<double> transfer;  ///< per listener [-]
};

/// @brief Evaluates a bubble's track at times that only increase (a cursor remembers the interval).
///        Before the first sample and after the last, the end values are held; tangents at the ends
///        are zero, so holding is C¹-continuous and a track end makes no click.
class TrackInterpolator {
 public:
  /// @param bubble    the bubble; its track may be empty (deep, transfer 1 on every channel)
  /// @param channels  number of listeners
  TrackInterpolator(const BubbleTrack& bubble, std::size_t channels);

  /// @brief Values at time t [s]; t must not decrease between calls.
  /// @param out  receives depth and one transfer per channel (resized as needed)
  void evaluate(double t, TrackValues& out);

  /// @brief Smallest depth over the track's samples [m] (+∞ without a track). The interpolant is
  ///        monotone between samples, so no interpolated depth is smaller.
  double minimumDepth() const;

 private:
  const BubbleTrack& bubble_;
  std::size_t channels_;
  std::size_t cursor_ = 0;  ///< index k of the interval [t_k, t_{k+1}] last used
};

/// @brief Fritsch–Butland tangent at an interior knot from its two neighbouring secants:
///        weighted harmonic mean, 0 when the secants differ in sign (keeps monotonicity).
/// @param h0,h1  interval lengths left and right [s]; @param d0,d1  secant slopes
double monotoneTangent(double h0, double h1, double d0, double d1);

}  // namespace fluidsound::acoustics
