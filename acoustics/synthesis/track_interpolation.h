// acoustics/synthesis/track_interpolation.h — smooth interpolation of a bubble track's per-frame values
// (depth, transfer) to any time, for the synthesizer: monotone cubic Hermite (Fritsch & Butland
// 1984), so no overshoot (depth never crosses the clamp it was given, transfer never changes sign)
// and a continuous first derivative (no zipper noise from frame-rate corners).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/synthesis/oscillator_bank.h"

namespace fluidsound::acoustics {

/// Values of a track at one instant.
struct TrackValues {
  double depth = 0.0;                              ///< h [m]; +∞ for a bubble without a track
  /// Per listener [-]; only the first `channels` entries are set (the rest are left
  /// uninitialised on purpose: this is filled once per bubble and block, in the hot path).
  std::array<double, kMaxListeners> transfer;
};

/// @brief A bubble's track prepared for evaluation at increasing times: the knot tangents are
///        computed once. Before the first sample and after the last, the end values are held;
///        tangents at the ends are zero, so holding is C¹-continuous and a track end makes no click.
class TrackInterpolator {
 public:
  /// @param bubble    the bubble; its track may be empty (deep, transfer 1 on every channel)
  /// @param channels  number of listeners, ≤ kMaxListeners
  TrackInterpolator(const BubbleTrack& bubble, std::size_t channels);

  /// @brief The same, keeping its tables in `storage` (storageSize(bubble, channels) doubles,
  ///        owned by the caller and outliving this object): many bubbles then share one
  ///        allocation, laid out in the order they are rendered.
  TrackInterpolator(const BubbleTrack& bubble, std::size_t channels, std::span<double> storage);

  /// Doubles of storage the tables of `bubble` need.
  static std::size_t storageSize(const BubbleTrack& bubble, std::size_t channels);

  /// An empty track on no channel, to be assigned a real one later.
  TrackInterpolator() = default;
  TrackInterpolator(TrackInterpolator&&) noexcept = default;
  TrackInterpolator& operator=(TrackInterpolator&&) noexcept = default;
  TrackInterpolator(const TrackInterpolator&) = delete;
  TrackInterpolator& operator=(const TrackInterpolator&) = delete;

  /// @brief Values at time t [s].
  /// @param cursor  interval index remembered between calls (start at 0); t must not decrease
  ///                between calls that share a cursor
  TrackValues evaluate(double t, std::size_t& cursor) const;

  /// @brief Smallest depth over the track's samples [m] (+∞ without a track). The interpolant is
  ///        monotone between samples, so no interpolated depth is smaller.
  double minimumDepth() const;

 private:
  std::size_t channels_ = 0;
  std::size_t knots_ = 0;
  /// Tables: knot times [s]; then per knot depth [m] and one transfer per channel; then per knot
  /// the tangents of the same quantities [1/s]. In owned_ or in the caller's storage.
  std::vector<double> owned_;
  const double* data_ = nullptr;
  void fill(const BubbleTrack& bubble, double* storage);
  const double* time() const { return data_; }
  const double* values() const { return data_ + knots_; }
  const double* slopes() const { return data_ + knots_ * (2 + channels_); }
};

/// @brief Fritsch–Butland tangent at an interior knot from its two neighbouring secants:
///        weighted harmonic mean, 0 when the secants differ in sign (keeps monotonicity).
/// @param h0,h1  interval lengths left and right [s]; @param d0,d1  secant slopes
double monotoneTangent(double h0, double h1, double d0, double d1);

}  // namespace fluidsound::acoustics
