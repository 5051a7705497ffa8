// acoustics/track_interpolation.cpp — monotone cubic Hermite interpolation of bubble tracks.
#include "acoustics/track_interpolation.h"

#include <algorithm>
#include <limits>

namespace fluidsound::acoustics {

double monotoneTangent(double h0, double h1, double d0, double d1) {
  // Fritsch & Butland (1984), "A method for constructing local monotone piecewise cubic
  // interpolants", SIAM J. Sci. Stat. Comput. 5(2):300: m = 3(h0+h1) / ((2h1+h0)/d0 + (h1+2h0)/d1).
  if (d0 * d1 <= 0.0) return 0.0;
  return 3.0 * (h0 + h1) / ((2.0 * h1 + h0) / d0 + (h1 + 2.0 * h0) / d1);
}

namespace {

/// Tangent of one scalar quantity at knot k; zero at the first and last knot.
template <typename ValueAt>
double tangentAt(std::span<const TrackSample> s, std::size_t k, ValueAt value) {
  if (k == 0 || k + 1 >= s.size()) return 0.0;
  const double h0 = s[k].time - s[k - 1].time;
  const double h1 = s[k + 1].time - s[k].time;
  const double d0 = (value(s[k]) - value(s[k - 1])) / h0;
  const double d1 = (value(s[k + 1]) - value(s[k])) / h1;
  return monotoneTangent(h0, h1, d0, d1);
}

/// Cubic Hermite on [t_k, t_k+1] with unit parameter u.
template <typename ValueAt>
double hermite(std::span<const TrackSample> s, std::size_t k, double u, ValueAt value) {
  const double h = s[k + 1].time - s[k].time;
  const double u2 = u * u, u3 = u2 * u;
  const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
  const double h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
  return h00 * value(s[k]) + h10 * h * tangentAt(s, k, value) + h01 * value(s[k + 1]) +
         h11 * h * tangentAt(s, k + 1, value);
}

}  // namespace

TrackInterpolator::TrackInterpolator(const BubbleTrack& bubble, std::size_t channels)
    : bubble_(bubble), channels_(channels) {}

double TrackInterpolator::minimumDepth() const {
  double h = std::numeric_limits<double>::infinity();
  for (const TrackSample& s : bubble_.track) h = std::min(h, s.depth);
  return h;
}

void TrackInterpolator::evaluate(double t, TrackValues& out) {
  out.transfer.resize(channels_);
  const std::span<const TrackSample> s(bubble_.track);
  if (s.empty()) {
    out.depth = std::numeric_limits<double>::infinity();
    std::fill(out.transfer.begin(), out.transfer.end(), 1.0);
    return;
  }
  const auto hold = [&](const TrackSample& at) {
    out.depth = at.depth;
    for (std::size_t c = 0; c < channels_; ++c) out.transfer[c] = at.transfer[c];
  };
  if (t <= s.front().time) return hold(s.front());
  if (t >= s.back().time) return hold(s.back());
  while (cursor_ + 2 < s.size() && s[cursor_ + 1].time <= t) ++cursor_;
  const std::size_t k = cursor_;
  const double u = (t - s[k].time) / (s[k + 1].time - s[k].time);
  out.depth = hermite(s, k, u, [](const TrackSample& x) { return x.depth; });
  for (std::size_t c = 0; c < channels_; ++c)
    out.transfer[c] = hermite(s, k, u, [c](const TrackSample& x) { return x.transfer[c]; });
}

}  // namespace fluidsound::acoustics
