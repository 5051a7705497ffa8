// tests/support/reference_distances.h — closed-form signed distances the geometry tests compare
// against, written independently of the code under test.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace fluidsound::test {

/// Signed distance [m] from p to the axis-aligned box [lo, hi]: outside, the distance to the
/// nearest point of the box (the clamped point); inside, minus the distance to the nearest face.
inline double referenceBoxDistance(const std::array<double, 3>& p, const std::array<double, 3>& lo,
                                   const std::array<double, 3>& hi) {
  double outside = 0.0, inside = std::numeric_limits<double>::infinity();
  bool isInside = true;
  for (int a = 0; a < 3; ++a) {
    const double q = std::clamp(p[a], lo[a], hi[a]);
    outside += (p[a] - q) * (p[a] - q);
    isInside = isInside && p[a] > lo[a] && p[a] < hi[a];
    inside = std::min({inside, p[a] - lo[a], hi[a] - p[a]});
  }
  return isInside ? -inside : std::sqrt(outside);
}

}  // namespace fluidsound::test
