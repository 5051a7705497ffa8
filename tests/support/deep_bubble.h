// tests/support/deep_bubble.h — a bubble's oscillator constants at the liquid's ambient pressure
// (no depth shift) and the frequency of its damped sine, for the tests that render bubbles.
#pragma once

#include <cmath>
#include <numbers>

#include "acoustics/bubble/bubble_oscillator.h"
#include "acoustics/synthesis/synthesizer.h"

namespace fluidsound::test {

/// ω₀, δ, β and amplitude of a bubble of `radius` [m] at the ambient pressure of `s.liquid`.
inline acoustics::OscillatorConstants deepConstants(double radius,
                                                    const acoustics::SynthesisSettings& s) {
  return acoustics::bubbleOscillator(radius, s.liquid.ambientPressure, s.liquid, s.model);
}

/// f_d = √(ω₀² − β²)/2π [Hz]: the frequency of the damped sine e^(−βt) sin(ω_d t).
inline double dampedFrequency(const acoustics::OscillatorConstants& c) {
  return std::sqrt(c.angularFrequency * c.angularFrequency - c.decayRate * c.decayRate) /
         (2.0 * std::numbers::pi);
}

}  // namespace fluidsound::test
