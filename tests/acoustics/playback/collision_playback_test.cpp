// Tests of acoustics/playback/collision_playback.h: the contact log played as recorded collision
// sounds, with the sample-playback paper's loudness model and the 1/r spreading to the listener.
#include "acoustics/playback/collision_playback.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace fluidsound::acoustics {
namespace {

double peakBetween(const std::vector<float>& x, std::size_t from, std::size_t to) {
  double p = 0.0;
  for (std::size_t i = from; i < to && i < x.size(); ++i) p = std::max(p, double(std::abs(x[i])));
  return p;
}

/// A 10 g ball (body 0) on the floor wall (−3): a touch at `speed` in `substep`, resting contacts after.
void touch(sim::ContactLog& log, long long substep, double speed, double friction = 0.0, double slide = 0.0) {
  sim::ContactRecord c;
  c.time = double(substep) * 1e-3;
  c.bodyA = 0;
  c.bodyB = -3;
  c.position = {0.0, 0.0, 0.0};
  c.normal = {0.0, 1.0, 0.0};
  c.normalImpulse = 1e-3;
  c.frictionImpulse = {friction * 1e-3, 0.0, 0.0};
  c.normalSpeed = speed;
  c.tangentialSpeed = slide;
  c.lifetime = 1;
  log.records.push_back(c);
}

// Claim (the sample-playback paper, shared solids.md T9): an impact at half the loudest's speed
// plays 6.02 dB (×0.5) quieter; the loudest plays the recording at peak_pa at 1 m, spread as 1/r
// (a listener 2 m away: ×0.5) and delayed by r/c; a touch below 0.02 m/s plays nothing. A slide
// plays its loop only while its friction force is at least 1 N. Reference: those laws, exactly
// (a unit click), to float rounding.
TEST(CollisionPlayback, ImpactsFollowTheLoudnessModelAndSlidesTheirThreshold) {
  sim::ContactLog log;
  log.bodies = {{"ball", 0.01, false, 0.005}};
  touch(log, 100, 1.0);   // the loudest
  touch(log, 300, 0.5);   // half the speed: −6.02 dB
  touch(log, 500, 0.01);  // below the threshold
  for (long long k = 700; k < 800; ++k) touch(log, k, 0.0, k < 750 ? 2.0 : 0.5, 0.3);  // slides, then too weak
  CollisionRecordings recordings;
  recordings.impact.samples = {1.0f};
  recordings.slide.samples = std::vector<float>(480, 1.0f);
  recordings.peakPascals = 3.0;
  CollisionPlaybackSettings settings;
  settings.samples = 48000;
  settings.listeners = {{0.0, 2.0, 0.0}};
  const PlaybackStems stems = renderCollisionPlayback(
      log, [&](int a, int b) { return a == 0 && b == -3 ? &recordings : nullptr; }, settings);
  const double delay = 2.0 / settings.soundSpeed;
  const auto at = [&](double t) { return static_cast<std::size_t>(std::llround((t + delay) * 48000.0)); };
  EXPECT_NEAR(stems.impacts[0][at(0.099)], 3.0 * 0.5, 1e-6);
  EXPECT_NEAR(stems.impacts[0][at(0.299)], 3.0 * 0.5 * 0.5, 1e-6);
  EXPECT_EQ(peakBetween(stems.impacts[0], at(0.45), at(0.6)), 0.0);
  EXPECT_EQ(stems.impactsPlayed, 2u);
  EXPECT_GT(peakBetween(stems.friction[0], at(0.71), at(0.74)), 0.1);
  EXPECT_EQ(peakBetween(stems.friction[0], at(0.76), at(0.9)), 0.0) << "below 1 N of friction it stops";
  EXPECT_EQ(stems.slideSubsteps, 50u);
  // Another pair's recording is not this one's: nothing plays.
  const PlaybackStems none = renderCollisionPlayback(log, [](int, int) { return nullptr; }, settings);
  EXPECT_EQ(peakBetween(none.impacts[0], 0, 48000) + peakBetween(none.friction[0], 0, 48000), 0.0);
}

}  // namespace
}  // namespace fluidsound::acoustics
