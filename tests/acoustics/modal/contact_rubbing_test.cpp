// tests/acoustics/modal/contact_rubbing_test.cpp — rubbing from Bullet's contact log on a static steel
// plate: a box pushed across it rubs only while it slides (the issue: "the sliding box makes sound
// only while it slides; bodies at rest make none"), and a rolling steel ball's force spectrum
// follows its speed (docs/solids.md, Rolling and sliding).
#include "acoustics/modal/contact_rubbing.h"
#include "acoustics/modal/stick_slip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include <unsupported/Eigen/FFT>

#include "support/body_contacts.h"
#include "support/steel_plate_model.h"

namespace fluidsound::acoustics {
namespace {

/// A free steel plate 0.6 × 0.01 × 0.6 m, centred on its body's origin: its lowest 4 modes.
const ModalModel& plateModel() {
  static const ModalModel model = test::steelPlateModel(0.6, 4);
  return model;
}

sim::RigidBodySpec plate() {
  sim::RigidBodySpec spec{"plate", sim::BoxShape{{0.3, 0.005, 0.3}}, 7850.0, true};
  spec.friction = 1.0;  // μ multiplies: the other body's μ is the pair's
  return spec;
}

double rms(const std::vector<Eigen::Vector3f>& f, std::size_t from, std::size_t to) {
  double sum = 0.0;
  for (std::size_t n = from; n < to; ++n) sum += f[n].squaredNorm();
  return std::sqrt(sum / static_cast<double>(to - from));
}

// A 4 × 2 × 4 cm steel box pushed at 1 m/s across the plate with μ = 0.3 decelerates at μg and
// stops after v/(μg) = 0.34 s: one touch, all of it sliding; its rubbing force after 0.4 s below
// 1e-3 of its RMS over 0.05–0.3 s, and its stick–slip breaks end with the slide.
TEST(ContactRubbing, PushedBoxRubsOnlyWhileItSlides) {
  sim::RigidBodySpec box{"box", sim::BoxShape{{0.02, 0.01, 0.02}}, 7850.0, false};
  box.position = {-0.1, 0.005 + 0.01, 0.0};
  box.velocity = {1.0, 0.0, 0.0};
  box.friction = 0.3;
  sim::RigidWorld world({plate(), box});
  world.advance(0.6);
  const std::vector<RubbingContact> touches = rubbingFromContacts(test::contactsOn(world, 0), plateModel(), 1e-3);
  ASSERT_EQ(touches.size(), 1u);
  const RubbingContact& touch = touches.front();
  EXPECT_EQ(touch.other, 1);
  EXPECT_EQ(touch.substeps.size(), 600u);
  const RubbingForce force = rubbingForce(touch.substeps, RoughnessProfile(25e-6, 1 << 16, 2.0, 1e-3, 0.05, 3), {});
  const double sliding = rms(force.force, 2400, 14400), resting = rms(force.force, 19200, force.force.size());
  EXPECT_GT(sliding, 0.01);  // κ·m·g ≈ 0.1·0.126 kg·9.81 m/s² = 0.12 N, times the speed's weight
  EXPECT_LT(resting, 1e-3 * sliding);
  for (std::size_t n = 2400; n < 14400; ++n) ASSERT_EQ(force.rolling[n], 0) << n;
  // Its stick–slip breaks (stick_slip.h): only while it slides, ever further apart as it slows
  // (every a₁/v²), each pushing the plate along the motion (the friction on the plate).
  const std::vector<ModalImpact> slips = stickSlipImpacts(touch.substeps, {});
  ASSERT_GT(slips.size(), 10u);
  EXPECT_LT(slips.back().time, 0.35);
  EXPECT_GT(slips.back().time - slips[slips.size() - 2].time, 4.0 * (slips[1].time - slips[0].time));
  for (const ModalImpact& slip : slips) EXPECT_GT(slip.impulse.x(), 0.0);
}

/// Spectral centroid [Hz] of the y component.
double centroid(const std::vector<Eigen::Vector3f>& f) {
  Eigen::FFT<double> fft;
  std::vector<double> in;
  for (const auto& v : f) in.push_back(v.y());
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, in);
  double weighted = 0.0, total = 0.0;
  for (std::size_t b = 1; b < spectrum.size() / 2; ++b) {
    weighted += std::norm(spectrum[b]) * b * 48000.0 / spectrum.size();
    total += std::norm(spectrum[b]);
  }
  return weighted / total;
}

// A 1 cm steel ball rolling without slipping (ω = v/r) over the same 0.5 m of plate at 0.25 m/s
// (2 s) and 0.5 m/s (1 s): rolling in every substep at the ball's speed (Bullet keeps a rolling
// ball's speed to 1e-6 without rolling resistance), and the force's spectral centroid doubles
// within 5 % (the speed's scaling, 2 % in the direct test, plus the contact node's steps on the
// 1 cm surface grid, which the force does not see: the same path is read in both runs).
TEST(ContactRubbing, RollingBallsForceSpectrumFollowsItsSpeed) {
  const auto roll = [&](double speed, double seconds) {
    sim::RigidBodySpec ball{"ball", sim::SphereShape{0.01}, 7850.0, false};
    ball.position = {-0.25, 0.005 + 0.01, 0.0};
    ball.velocity = {speed, 0.0, 0.0};
    ball.angularVelocity = {0.0, 0.0, -speed / 0.01};
    sim::RigidWorld world({plate(), ball});
    world.advance(seconds);
    const auto touches = rubbingFromContacts(test::contactsOn(world, 0), plateModel(), 1e-3);
    EXPECT_EQ(touches.size(), 1u);
    for (const RubbingSample& s : touches.front().substeps) {
      EXPECT_TRUE(s.rolling);
      EXPECT_NEAR(s.speed, speed, 1e-3 * speed);
    }
    return rubbingForce(touches.front().substeps, RoughnessProfile(25e-6, 1 << 16, 2.0, 1e-3, 0.05, 5), {});
  };
  const RubbingForce slow = roll(0.25, 2.0), fast = roll(0.5, 1.0);
  EXPECT_NEAR(centroid(fast.force) / centroid(slow.force), 2.0, 0.1);
}

}  // namespace
}  // namespace fluidsound::acoustics
