// acoustics/bubble/bubble_oscillator.h — the constants of one bubble's damped oscillator, gathered from
// minnaert.h, damping.h and excitation.h for the synthesizer and `fluidsound validate`.
#pragma once

#include <optional>

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/bubble/oscillator_model.h"

namespace fluidsound::acoustics {

/// The constants of a bubble oscillator deep in open water (no free-surface shift).
struct OscillatorConstants {
  double angularFrequency = 0.0;  ///< ω₀ [rad/s], undamped natural angular frequency
  double dampingConstant = 0.0;   ///< δ [-]
  double decayRate = 0.0;         ///< β [1/s], amplitude decay rate
  double amplitude = 0.0;         ///< free-field pressure amplitude at 1 m [Pa]
};

/// @brief Oscillator constants of a bubble of radius R [m] at ambient pressure p_amb [Pa].
/// @param amplitude  Pa at 1 m, if given (a bubble file's `amplitude`); else the excitation model's
OscillatorConstants bubbleOscillator(double radius, double ambientPressure,
                                     const LiquidProperties& liquid, const OscillatorModel& model,
                                     std::optional<double> amplitude = std::nullopt);

}  // namespace fluidsound::acoustics
