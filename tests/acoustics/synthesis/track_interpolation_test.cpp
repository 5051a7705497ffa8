// Tests of acoustics/synthesis/track_interpolation.h: the smooth per-sample values of a bubble track.
#include "acoustics/synthesis/track_interpolation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fluidsound::acoustics {
namespace {

BubbleTrack track(std::initializer_list<std::pair<double, double>> timeDepth) {
  BubbleTrack b;
  b.radius = 1e-3;
  for (const auto& [t, h] : timeDepth) b.track.push_back({t, h, {h * 10.0}, std::nullopt});
  return b;
}

// The interpolant passes through every frame value (it is an interpolant, not a smoother).
TEST(TrackInterpolation, PassesThroughSamples) {
  const BubbleTrack b = track({{0.0, 0.03}, {1 / 30.0, 0.02}, {2 / 30.0, 0.025}, {3 / 30.0, 0.01}});
  const TrackInterpolator interp(b, 1);
  std::size_t cursor = 0;
  for (const TrackSample& s : b.track) {
    const TrackValues v = interp.evaluate(s.time, cursor);
    EXPECT_DOUBLE_EQ(v.depth, s.depth);
    EXPECT_DOUBLE_EQ(v.transfer[0], s.transfer[0]);
  }
}

// Monotone data stay monotone and inside the data range between samples (Fritsch–Butland), so
// an interpolated depth never goes below the shallowest frame value (the Nyquist guard relies on it).
TEST(TrackInterpolation, NoOvershootBetweenSamples) {
  const BubbleTrack b = track({{0.0, 0.04}, {0.1, 0.039}, {0.2, 0.01}, {0.3, 0.0099}, {0.4, 0.0098}});
  const TrackInterpolator interp(b, 1);
  std::size_t cursor = 0;
  double previous = 1.0;
  for (double t = 0.0; t <= 0.4; t += 1e-4) {
    const TrackValues v = interp.evaluate(t, cursor);
    EXPECT_LE(v.depth, previous + 1e-15) << "t = " << t;
    EXPECT_GE(v.depth, 0.0098 - 1e-15) << "t = " << t;
    previous = v.depth;
  }
}

// C¹ continuity: the slopes just left and right of an interior sample agree (no frame-rate
// corners, which would be heard as zipper noise). Finite differences over ε = 1e-7 s with values
// O(0.03 m): slope error O(ε·h''), relative tolerance 1e-4.
TEST(TrackInterpolation, SlopeIsContinuousAtSamples) {
  const BubbleTrack b = track({{0.0, 0.03}, {0.05, 0.02}, {0.1, 0.012}, {0.15, 0.008}});
  constexpr double eps = 1e-7;
  for (const double knot : {0.05, 0.1}) {
    const TrackInterpolator interp(b, 1);
    std::size_t cursor = 0;
    const TrackValues a = interp.evaluate(knot - eps, cursor);
    const TrackValues m = interp.evaluate(knot, cursor);
    const TrackValues c = interp.evaluate(knot + eps, cursor);
    const double left = (m.depth - a.depth) / eps, right = (c.depth - m.depth) / eps;
    EXPECT_NEAR(left, right, 1e-4 * std::fabs(left) + 1e-9) << "knot " << knot;
  }
}

// Before the first and after the last sample the end values hold (DESIGN.md: the bubble keeps
// its last values and rings out); a bubble without a track is deep with transfer 1.
TEST(TrackInterpolation, HoldsEndValuesAndDefaultsWithoutTrack) {
  const BubbleTrack b = track({{0.1, 0.03}, {0.2, 0.02}});
  const TrackInterpolator interp(b, 1);
  std::size_t cursor = 0;
  EXPECT_DOUBLE_EQ(interp.evaluate(0.0, cursor).depth, 0.03);
  EXPECT_DOUBLE_EQ(interp.evaluate(5.0, cursor).depth, 0.02);
  BubbleTrack deep;
  deep.radius = 1e-3;
  const TrackInterpolator none(deep, 2);
  std::size_t noneCursor = 0;
  const TrackValues v = none.evaluate(0.3, noneCursor);
  EXPECT_TRUE(std::isinf(v.depth));
  EXPECT_EQ(v.transfer[0], 1.0);
  EXPECT_EQ(v.transfer[1], 1.0);
}

}  // namespace
}  // namespace fluidsound::acoustics
