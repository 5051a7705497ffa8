// tests/acoustics/modal/surface_roughness_test.cpp — the rough surface's spectrum, the rubbing force
// whose spectrum follows the contact's speed, silence at rest, and the modes driven by a force
// against the damped oscillator's exact step response (docs/solids.md, Rolling and sliding).
#include "acoustics/modal/surface_roughness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <unsupported/Eigen/FFT>

#include "acoustics/modal/modal_synthesis.h"

namespace fluidsound::acoustics {
namespace {

constexpr double kPi = std::numbers::pi;

RoughnessProfile surface() { return RoughnessProfile(25e-6, 1 << 16, 2.0, 1e-3, 0.05, 11); }

// The profile's amplitudes are the power law itself (only the phases are random): its spectrum is
// k^(−β/2) inside the band to rounding, nothing outside; zero mean, unit RMS.
TEST(SurfaceRoughness, ProfileHasItsPowerLawSpectrumInsideTheBand) {
  const RoughnessProfile profile = surface();
  const std::size_t n = 1 << 16;
  std::vector<double> h(n);
  double sum = 0.0, squares = 0.0;
  for (std::size_t i = 0; i < n; ++i) h[i] = profile.height(i * profile.spacing()), sum += h[i], squares += h[i] * h[i];
  EXPECT_NEAR(sum / n, 0.0, 1e-9);
  EXPECT_NEAR(std::sqrt(squares / n), 1.0, 1e-9);
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, h);
  const double length = profile.length();
  double reference = 0.0;
  for (std::size_t m = 1; m < n / 2; ++m) {
    const double k = m / length, magnitude = std::abs(spectrum[m]);
    if (1.0 / k < 1e-3 || 1.0 / k > 0.05) {
      EXPECT_LT(magnitude, 1e-9) << m;
      continue;
    }
    const double scaled = magnitude * std::pow(k, 1.0);  // × k^(β/2): constant inside the band
    if (reference == 0.0) reference = scaled;
    EXPECT_NEAR(scaled, reference, 1e-9 * reference) << m;
  }
}

/// Spectral centroid [Hz] of x at `rate`.
double centroid(const std::vector<float>& x, double rate) {
  Eigen::FFT<double> fft;
  std::vector<double> in(x.begin(), x.end());
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, in);
  double weighted = 0.0, total = 0.0;
  for (std::size_t b = 1; b < spectrum.size() / 2; ++b) {
    const double p = std::norm(spectrum[b]);
    weighted += p * b * rate / spectrum.size();
    total += p;
  }
  return weighted / total;
}

std::vector<RubbingSample> steady(double load, double speed, double seconds) {
  std::vector<RubbingSample> s;
  for (int i = 1; i <= static_cast<int>(std::lround(seconds * 1000)); ++i) s.push_back({i * 1e-3, load, speed, {0, 1, 0}});
  return s;
}

// The force's spectrum is the surface's at f = v·k: over the same metre of surface, read at 0.5
// m/s for 2 s and at 1 m/s for 1 s, doubling the speed doubles the force's spectral centroid (the
// band 1 mm – 5 cm lies at 10–1 000 Hz, far below Nyquist; the two signals are the same function
// of s sampled twice as densely in s at the slower speed, so 2 % is the linear interpolation's
// and the spectra's bin-rounding share). Over different stretches the centroid of this random
// surface differs by a few per cent on its own (3.6 % between the first half metre and metre).
TEST(SurfaceRoughness, ForceSpectrumFollowsTheContactsSpeed) {
  const RoughnessProfile profile = surface();
  std::vector<float> slow, fast;
  for (const auto& f : rubbingForce(steady(2.0, 0.5, 2.0), profile, {}).force) slow.push_back(f.y());
  for (const auto& f : rubbingForce(steady(2.0, 1.0, 1.0), profile, {}).force) fast.push_back(f.y());
  ASSERT_EQ(slow.size(), 96000u);
  EXPECT_NEAR(centroid(fast, 48000.0) / centroid(slow, 48000.0), 2.0, 0.04);
  double rms = 0.0;
  for (float v : fast) rms += v * v;
  rms = std::sqrt(rms / fast.size());
  // κ·F_n·v/(v + v₀) with unit-RMS heights: 0.1·2·(1/1.001), within the RMS's sampling (1 s of
  // a profile 1.6 m long: the first 1 m of it, 5 %).
  EXPECT_NEAR(rms, 0.2 / 1.001, 0.05 * 0.2);
}

// A box that slides for 0.3 s and then rests (Bullet's resting speed ~1e-7 m/s) under the same
// load: the force at rest is below 1e-3 of the sliding force's RMS.
TEST(SurfaceRoughness, ContactAtRestIsSilent) {
  std::vector<RubbingSample> log = steady(5.0, 0.4, 0.3);
  for (int i = 301; i <= 600; ++i) log.push_back({i * 1e-3, 5.0, 1e-7, {0, 1, 0}});
  const RubbingForce force = rubbingForce(log, surface(), {});
  double sliding = 0.0, resting = 0.0;
  for (std::size_t n = 0; n < force.force.size(); ++n) {
    const double t = force.startTime + (n + 0.5) / 48000.0, f2 = force.force[n].squaredNorm();
    if (t < 0.29) sliding = std::max(sliding, f2);
    if (t > 0.31) resting = std::max(resting, f2);
  }
  EXPECT_GT(sliding, 0.0);
  EXPECT_LT(std::sqrt(resting), 1e-3 * std::sqrt(sliding));
}

// A step force F on one mode (m = 1, 300 Hz, ξ = 0.01): the exact step response
// q = (F/ω²)(1 − e^{−dt}(cos ω_d t + (d/ω_d) sin ω_d t)) at every sample to float rounding.
TEST(SurfaceRoughness, ModesFollowAForceExactly) {
  ModalModel model;
  const double f = 300.0, omega = 2 * kPi * f, d = 0.01 * omega, omegaD = std::sqrt(omega * omega - d * d);
  model.frequency = {f};
  model.decayRate = {d};
  model.dampedFrequency = {omegaD / (2 * kPi)};
  model.surfaceNodes = {0};
  model.surfacePositions = {Eigen::Vector3d::Zero()};
  model.surfaceShapes = Eigen::MatrixXf::Zero(3, 1);
  model.surfaceShapes(1, 0) = 1.0f;
  const std::vector<Eigen::Vector3f> step(4800, Eigen::Vector3f(0.0f, 2.0f, 0.0f));
  const std::size_t node = 0;
  const ModalForce force{0.0, step, {&node, 1}};
  const std::vector<std::complex<double>> gains{1.0};
  const std::vector<float> q = synthesizeModalForces(model, {&force, 1}, gains, 4800, 0.0, {});
  const double statics = 2.0 / (omega * omega);
  for (std::size_t n = 0; n < q.size(); ++n) {
    const double t = n / 48000.0;
    const double exact = statics * (1.0 - std::exp(-d * t) * (std::cos(omegaD * t) + d / omegaD * std::sin(omegaD * t)));
    ASSERT_NEAR(q[n], exact, 1e-5 * statics) << n;
  }
}

// Several forces drive each mode in one pass: two overlapping forces (at 0 and 20 ms) render as the
// sum of their renders alone (linearity), to float rounding.
TEST(SurfaceRoughness, ForcesAddUp) {
  ModalModel model;
  model.frequency = {300.0, 1200.0};
  model.decayRate = {5.0, 20.0};
  model.dampedFrequency = {300.0, 1200.0};
  model.surfaceNodes = {0};
  model.surfacePositions = {Eigen::Vector3d::Zero()};
  model.surfaceShapes = Eigen::MatrixXf::Zero(3, 2);
  model.surfaceShapes(1, 0) = 1.0f;
  model.surfaceShapes(0, 1) = 0.5f;
  const std::vector<Eigen::Vector3f> a(2400, Eigen::Vector3f(0.3f, 1.0f, 0.0f)), b(1200, Eigen::Vector3f(1.0f, -2.0f, 0.0f));
  const std::size_t node = 0;
  const ModalForce both[] = {{0.0, a, {&node, 1}}, {0.02, b, {&node, 1}}};
  const std::vector<std::complex<double>> gains{1.0, std::complex<double>(0.0, 2.0)};
  const std::vector<float> sum = synthesizeModalForces(model, both, gains, 9600, 0.0, {});
  const std::vector<float> first = synthesizeModalForces(model, {&both[0], 1}, gains, 9600, 0.0, {});
  const std::vector<float> second = synthesizeModalForces(model, {&both[1], 1}, gains, 9600, 0.0, {});
  float peak = 0.0f;
  for (float v : sum) peak = std::max(peak, std::abs(v));
  ASSERT_GT(peak, 0.0f);
  for (std::size_t n = 0; n < sum.size(); ++n) ASSERT_NEAR(sum[n], first[n] + second[n], 1e-5f * peak) << n;
}

}  // namespace
}  // namespace fluidsound::acoustics
