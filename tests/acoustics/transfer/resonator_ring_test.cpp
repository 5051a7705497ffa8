// tests/acoustics/transfer/resonator_ring_test.cpp — the free ring a bubble leaves in a resonant
// transfer (resonator_ring.h), against the same linear system integrated in time, and the ring
// as the synthesizer adds it (acoustics/synthesis/resonator_rings.h).
#include "acoustics/transfer/resonator_ring.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "acoustics/bubble/instantaneous_frequency.h"
#include "acoustics/synthesis/resonator_rings.h"

namespace fluidsound::acoustics {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

// Reference: the listener's sound y = h * s for a resonant transfer T(s) = R/(s − p) + c.c., i.e.
// z' = p z + R s(t), y = 2 Re z, driven by a bubble s(t) = A e^{−β_b t} sin ω_b t and integrated
// with RK4 at 1 µs (error ~ (ω dt)⁴, 10⁻⁸). Once the bubble has died away (β_b > β_r) what is left
// is the ring alone, A·Re[c e^{pt}], c = ringAmplitude(R, p, ω_b, β_b): 10⁻⁴ allowed (the bubble's
// own part, e^{−β_b t}, is below 10⁻⁶ of it by then). A bubble above the resonance, one below,
// and a complex residue.
TEST(ResonatorRing, TheRingIsWhatTheResonatorSoundsAfterTheBubble) {
  const double amplitude = 0.3;
  struct Case {
    double ringHz, ringDecay, bubbleHz, bubbleDecay;
    Complex residue;
  };
  for (const Case& c : {Case{900.0, 150.0, 3000.0, 900.0, {40.0, 0.0}},
                        Case{1200.0, 300.0, 700.0, 1500.0, {-25.0, 60.0}}}) {
    const Complex pole(-c.ringDecay, 2.0 * kPi * c.ringHz);
    const double wb = 2.0 * kPi * c.bubbleHz, bb = c.bubbleDecay;
    const auto source = [&](double t) { return amplitude * std::exp(-bb * t) * std::sin(wb * t); };
    const auto rate = [&](double t, Complex z) { return pole * z + c.residue * source(t); };
    const double dt = 1e-6, end = 0.02;
    Complex z(0.0);
    for (double t = 0.0; t < end - dt / 2; t += dt) {
      const Complex k1 = rate(t, z), k2 = rate(t + dt / 2, z + dt / 2 * k1),
                    k3 = rate(t + dt / 2, z + dt / 2 * k2), k4 = rate(t + dt, z + dt * k3);
      z += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    const double integrated = 2.0 * z.real();
    const Complex ring = ringAmplitude(c.residue, pole, wb, bb);
    const double predicted = amplitude * (ring * std::exp(pole * end)).real();
    const double scale = amplitude * std::abs(ring) * std::exp(-c.ringDecay * end);
    EXPECT_NEAR(integrated, predicted, 1e-4 * scale) << c.ringHz << " Hz ring, " << c.bubbleHz << " Hz bubble";
  }
}

// The synthesizer adds A·gain·e^{−β τ}cos(2πfτ + phase) from birth, A the bubble's amplitude: the
// exact recurrence against the closed form at every sample, until it has decayed by 90 dB as the
// bubbles do (float output: 10⁻⁶ of the peak).
TEST(ResonatorRing, TheSynthesizerAddsTheRingFromTheBubblesBirth) {
  BubbleTrackSet tracks;
  tracks.sampleRate = 48000.0;
  tracks.listeners = {"a", "b"};
  BubbleTrack bubble;
  bubble.radius = 0.002;
  bubble.birth = 0.01001;  // between samples
  bubble.amplitude = 0.5;
  bubble.rings = {ResonatorRing{1000.0, 200.0, {0.2, 0.05}, {0.3, -1.2}}};
  const ResonatorRing& ring = bubble.rings.front();
  tracks.bubbles = {bubble};
  SynthesisSettings settings;
  settings.sampleRate = 48000.0;
  std::vector<std::vector<float>> channels(2, std::vector<float>(4800, 0.0f));
  const std::int64_t added = addResonatorRings(tracks, settings, channels);
  EXPECT_GT(added, 0);
  for (std::size_t l = 0; l < 2; ++l) {
    double worst = 0.0;
    for (std::size_t n = 0; n < channels[l].size(); ++n) {
      const double tau = n / settings.sampleRate - bubble.birth;
      const bool ringing = tau >= 0 && tau < decayTime(200.0, settings.cutoffDecibels);  // cut at 90 dB
      const double exact = !ringing ? 0.0
                                   : 0.5 * ring.gain[l] * std::exp(-200.0 * tau) *
                                         std::cos(2.0 * kPi * 1000.0 * tau + ring.phase[l]);
      worst = std::max(worst, std::abs(channels[l][n] - exact));
    }
    EXPECT_LT(worst, 1e-6 * 0.5 * ring.gain[l]) << "listener " << l;
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
