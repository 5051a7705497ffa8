// acoustics/bubble/damping.h — decay of a bubble's oscillation: radiative, viscous and thermal damping
// constants (Devin 1959), and van den Doel's (2005) graphics formula. docs/physics.md §4.
#pragma once

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/bubble/oscillator_model.h"

namespace fluidsound::acoustics {

/// @brief Radiation damping constant δ_rad = ω₀R/c_w [-] (= kR; Harmonic Fluids, Langlois 2016).
double radiativeDampingConstant(double angularFrequency, double radius, const LiquidProperties& liquid);

/// @brief Viscous damping constant δ_vis = 4μ/(ρω₀R²) [-] (Langlois 2016 / Xue 2023 code).
double viscousDampingConstant(double angularFrequency, double radius, const LiquidProperties& liquid);

/// @brief Thermal damping constant, exact Devin (1959) form, X = R√(2ω/D_g):
///        δ_th = 3(γ−1)[X(sinh X + sin X) − 2(cosh X − cos X)]
///               / [X²(cosh X − cos X) + 3(γ−1)X(sinh X − sin X)]   [-]
///        evaluated with e^X factored out (no overflow for large X).
/// @param gasPressure  p_g0 [Pa], where D_g is evaluated
double thermalDampingConstant(double angularFrequency, double radius, double gasPressure,
                              const GasProperties& gas);

/// @brief van den Doel (2005) amplitude decay rate d = 0.13/r + 0.0072 r^(−3/2) [1/s], r in m.
double vanDenDoelDecayRate(double radius);

/// @brief Total damping of a bubble at its natural frequency.
struct Damping {
  double dampingConstant = 0.0;  ///< δ = 2β/ω₀ [-]
  double decayRate = 0.0;        ///< β [1/s], amplitude decay rate, p ∝ e^(−βt)
};

/// @brief Damping of a bubble by the chosen model: Devin → δ = δ_rad + δ_vis + δ_th and
///        β = ω₀δ/2; with PolytropicModel::Thermal the thermal term is p_g0|Im Φ|/(ρR²ω₀²);
///        VanDenDoel → β = d, δ = 2d/ω₀.
/// @param angularFrequency  ω₀ [rad/s] from naturalAngularFrequency
/// @param gasPressure       p_g0 [Pa] from gasPressure
Damping bubbleDamping(double radius, double angularFrequency, double gasPressure,
                      const LiquidProperties& liquid, const OscillatorModel& model);

}  // namespace fluidsound::acoustics
