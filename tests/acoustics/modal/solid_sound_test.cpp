// Tests of acoustics/modal/solid_sound.h, the solids' stage: a steel plate struck by a dropped
// ball rings in the impacts stem, its loudness falls as 1/r with the listener's distance, a moving
// body heard window by window sounds as one heard once when it does not move, and the result is
// linear in the impulse.
#include "acoustics/modal/solid_sound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "acoustics/modal/voxel_solid.h"
#include "sim/bodies/rigid_world.h"
#include "support/body_contacts.h"
#include "support/steel_plate_model.h"

namespace fluidsound::acoustics {
namespace {

/// A free steel plate 0.2 × 0.01 × 0.2 m, centred on its body's origin: its lowest 20 modes.
const ModalModel& plateModel() {
  static const ModalModel model = test::steelPlateModel(0.2, 20);
  return model;
}

/// A 1 cm steel ball dropped 5 cm onto the static plate (its top at y = 0.005), 0.3 s logged.
sim::ContactLog droppedBall() {
  sim::RigidBodySpec plate{"plate", sim::BoxShape{{0.1, 0.005, 0.1}}, 7850.0, true};
  sim::RigidBodySpec ball{"ball", sim::SphereShape{0.01}, 7850.0, false, {0.0, 0.065, 0.0}};
  plate.restitution = 1.0;  // the pair's is the product: the ball's 0.5
  ball.restitution = 0.5;
  sim::RigidWorld world({plate, ball}, {});
  world.advance(0.3);
  sim::ContactLog log = test::contactLogOf(world);
  log.bodies[1].contactRadius = 0.01;
  return log;
}

double peak(const std::vector<float>& x) {
  double p = 0.0;
  for (float v : x) p = std::max(p, double(std::abs(v)));
  return p;
}

SolidStems render(const sim::ContactLog& log, std::vector<Eigen::Vector3d> listeners, double window = 0.01,
                  double truncation = 1e-5) {
  const std::vector<SoundingBody> bodies = {{&plateModel(), *findSolidMaterial("steel")},
                                            {nullptr, *findSolidMaterial("steel")}};
  SolidSoundSettings settings;
  settings.samples = static_cast<std::size_t>(0.3 * settings.sampleRate);
  settings.listeners = std::move(listeners);
  settings.radiationWindow = window;
  settings.truncation = truncation;
  StageObserver quiet;
  return renderSolidSound(log, bodies, settings, quiet);
}

// Claim: the dropped ball's bounces ring the plate in the impacts stem, and a far listener hears
// it as 1/r (mode_radiation.h): at 3 m and 6 m from the plate, in one direction off its axis
// (on the axis a free plate's modes, which displace no net volume, cancel to 1/r²), the peak
// halves. Tolerance 5 %: path differences across the plate (its size² / 2r: 1e-2 m at 3 m) and
// the delay's shift of the peak sample. The resting ball adds nothing to the rolling and
// friction stems; the ball itself (no modes) is silent.
TEST(SolidSound, DroppedBallRingsThePlateAndItFallsAsOneOverR) {
  const sim::ContactLog log = droppedBall();
  const Eigen::Vector3d direction = Eigen::Vector3d(1.0, 2.0, 0.5).normalized();
  const SolidStems stems = render(log, {3.0 * direction, 6.0 * direction});
  ASSERT_EQ(stems.impacts.size(), 2u);
  EXPECT_GE(stems.bodies[0].impacts, 2u) << "the ball bounces";
  const double near = peak(stems.impacts[0]), far = peak(stems.impacts[1]);
  ASSERT_GT(near, 0.0);
  EXPECT_NEAR(far / near, 0.5, 0.05 * 0.5);
  EXPECT_LT(peak(stems.rolling[0]), 1e-3 * near);
  EXPECT_LT(peak(stems.friction[0]), 1e-3 * near);
  EXPECT_EQ(stems.bodies[1].impacts, 0u) << "the ball has no modes: silent";
}

// Claim: the stage is linear in the contacts' impulses (the modes are linear oscillators): the
// same log with every impulse doubled renders twice the impacts, to float rounding (1e-6 of the
// peak). And a body logged as moving but standing still, heard from its pose window by window
// (each window's events rung separately), sounds as the same body heard once as a static one, to
// float rounding with truncation off (with it, a weak event rung alone rings down to its own
// floor instead of the loudest event's: differences up to modes × 1e-5 of the peak).
TEST(SolidSound, LinearInTheImpulseAndTheSameWindowByWindow) {
  const sim::ContactLog log = droppedBall();
  sim::ContactLog twice = log;
  for (sim::ContactRecord& c : twice.records) {
    c.normalImpulse *= 2.0;
    for (double& f : c.frictionImpulse) f *= 2.0;
  }
  const Eigen::Vector3d listener(0.3, 0.5, 0.2);
  const std::vector<float> one = render(log, {listener}).impacts[0], two = render(twice, {listener}).impacts[0];
  const double loudest = peak(one);
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_NEAR(two[i], 2.0 * one[i], 1e-6 * loudest) << i;

  // Where a body is comes from each record's point, midway between the two bodies' surfaces:
  // during an impact Bullet lets them overlap by up to v·Δt (1 mm at 1 m/s), which moves the
  // place by half that (a phase of 0.05 rad at 5 kHz). Here every point is put on the plate's
  // surface, so that both renders hear the plate from exactly where it is.
  sim::ContactLog snapped = log;
  for (sim::ContactRecord& c : snapped.records) c.position = c.localPointB;  // the plate is B, unturned, at the origin
  const sim::ContactLog& base = snapped;
  sim::ContactLog moving = snapped;
  moving.bodies[0].isStatic = false;
  moving.bodies[0].mass = 1e6;  // (only the Hertz durations read it: make it immovable there too)
  moving.bodies[0].contactRadius = 1e9;
  const std::vector<float> whole = render(base, {listener}, 0.01, 0.0).impacts[0];
  const std::vector<float> windowed = render(moving, {listener}, 0.005, 0.0).impacts[0];
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_NEAR(windowed[i], whole[i], 1e-6 * loudest) << i;
}

// Claim (sound_occlusion.h): another body on the straight path to the listener shadows the plate:
// each mode by Maekawa's attenuation, at least 4.77 dB (a factor ≤ 0.577, energy ≤ 1/3), so the
// struck plate's sound energy at the listener falls below 0.4 of the open path's (the modes'
// cross terms average out over 0.3 s); an occluder off the path changes nothing, bit for bit.
TEST(SolidSound, ABodyInTheWayShadowsThePlate) {
  const sim::ContactLog log = droppedBall();
  const Eigen::Vector3d listener(0.0, 1.0, 0.8);
  const std::vector<SoundingBody> bodies = {{&plateModel(), *findSolidMaterial("steel")},
                                            {nullptr, *findSolidMaterial("steel")}};
  const auto energy = [&](const std::vector<Occluder>& occluders) {
    SolidSoundSettings settings;
    settings.samples = static_cast<std::size_t>(0.3 * settings.sampleRate);
    settings.listeners = {listener};
    settings.occluders = occluders;
    StageObserver quiet;
    const SolidStems stems = renderSolidSound(log, bodies, settings, quiet);
    double sum = 0.0;
    for (float v : stems.impacts[0]) sum += double(v) * v;
    return sum;
  };
  const auto always = [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return true; };
  const auto never = [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return false; };
  const double open = energy({});
  ASSERT_GT(open, 0.0);
  EXPECT_LT(energy({{7, Eigen::Vector3d(0.0, 0.5, 0.4), 0.2, always}}), 0.4 * open);
  EXPECT_EQ(energy({{7, Eigen::Vector3d(0.0, 0.5, 0.4), 0.2, never}}), open);
}

}  // namespace
}  // namespace fluidsound::acoustics
