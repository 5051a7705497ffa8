// acoustics/synthesis/track_interpolation.cpp — monotone cubic Hermite interpolation of bubble tracks.
#include "acoustics/synthesis/track_interpolation.h"

#include <algorithm>
#include <limits>

namespace fluidsound::acoustics {

double monotoneTangent(double h0, double h1, double d0, double d1) {
  // Fritsch & Butland (1984), "A method for constructing local monotone piecewise cubic
  // interpolants", SIAM J. Sci. Stat. Comput. 5(2):300: m = 3(h0+h1) / ((2h1+h0)/d0 + (h1+2h0)/d1).
  if (d0 * d1 <= 0.0) return 0.0;
  return 3.0 * (h0 + h1) / ((2.0 * h1 + h0) / d0 + (h1 + 2.0 * h0) / d1);
}

std::size_t TrackInterpolator::storageSize(const BubbleTrack& bubble, std::size_t channels) {
  return bubble.track.size() * (1 + 2 * (1 + channels));
}

TrackInterpolator::TrackInterpolator(const BubbleTrack& bubble, std::size_t channels)
    : channels_(channels), knots_(bubble.track.size()), owned_(storageSize(bubble, channels)) {
  fill(bubble, owned_.data());
}

TrackInterpolator::TrackInterpolator(const BubbleTrack& bubble, std::size_t channels,
                                     std::span<double> storage)
    : channels_(channels), knots_(bubble.track.size()) {
  fill(bubble, storage.data());
}

void TrackInterpolator::fill(const BubbleTrack& bubble, double* storage) {
  const std::size_t width = 1 + channels_, channels = channels_;
  data_ = storage;
  double* time = storage;
  double* values = time + knots_;
  double* slopes = values + knots_ * width;
  std::fill(slopes, slopes + knots_ * width, 0.0);  // tangents zero at both ends
  for (std::size_t k = 0; k < knots_; ++k) {
    const TrackSample& s = bubble.track[k];
    time[k] = s.time;
    values[k * width] = s.depth;
    for (std::size_t c = 0; c < channels; ++c) values[k * width + 1 + c] = s.transfer[c];
  }
  for (std::size_t k = 1; k + 1 < knots_; ++k) {
    const double h0 = time[k] - time[k - 1], h1 = time[k + 1] - time[k];
    for (std::size_t q = 0; q < width; ++q) {
      const double d0 = (values[k * width + q] - values[(k - 1) * width + q]) / h0;
      const double d1 = (values[(k + 1) * width + q] - values[k * width + q]) / h1;
      slopes[k * width + q] = monotoneTangent(h0, h1, d0, d1);
    }
  }
}

double TrackInterpolator::minimumDepth() const {
  double h = std::numeric_limits<double>::infinity();
  const std::size_t width = 1 + channels_;
  for (std::size_t k = 0; k < knots_; ++k) h = std::min(h, values()[k * width]);
  return h;
}

TrackValues TrackInterpolator::evaluate(double t, std::size_t& cursor) const {
  TrackValues out;
  const std::size_t width = 1 + channels_;
  if (knots_ == 0) {
    out.depth = std::numeric_limits<double>::infinity();
    std::fill(out.transfer.begin(), out.transfer.begin() + static_cast<std::ptrdiff_t>(channels_), 1.0);
    return out;
  }
  const double* time = this->time();
  const auto hold = [&](std::size_t k) {
    const double* v = values() + k * width;
    out.depth = v[0];
    for (std::size_t c = 0; c < channels_; ++c) out.transfer[c] = v[1 + c];
    return out;
  };
  if (t <= time[0]) return hold(0);
  if (t >= time[knots_ - 1]) return hold(knots_ - 1);
  while (cursor + 2 < knots_ && time[cursor + 1] <= t) ++cursor;
  const std::size_t k = cursor;
  const double h = time[k + 1] - time[k];
  const double u = (t - time[k]) / h, u2 = u * u, u3 = u2 * u;
  // Cubic Hermite basis on the unit interval.
  const double h00 = 2 * u3 - 3 * u2 + 1, h10 = (u3 - 2 * u2 + u) * h;
  const double h01 = -2 * u3 + 3 * u2, h11 = (u3 - u2) * h;
  const double* a = values() + k * width;
  const double* b = a + width;
  const double* ma = slopes() + k * width;
  const double* mb = ma + width;
  out.depth = h00 * a[0] + h10 * ma[0] + h01 * b[0] + h11 * mb[0];
  for (std::size_t c = 1; c <= channels_; ++c)
    out.transfer[c - 1] = h00 * a[c] + h10 * ma[c] + h01 * b[c] + h11 * mb[c];
  return out;
}

}  // namespace fluidsound::acoustics
