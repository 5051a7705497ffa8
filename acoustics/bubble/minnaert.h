// acoustics/bubble/minnaert.h — natural (undamped) resonance frequency of a gas bubble in a liquid:
// Minnaert (1933) with surface tension, optional vapour pressure and the thermal effective
// polytropic index of Prosperetti (1977, 1991) / Devin (1959). docs/physics.md §3.
#pragma once

#include <complex>

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/bubble/oscillator_model.h"

namespace fluidsound::acoustics {

/// @brief Basic Minnaert frequency f₀ = √(3γp₀/ρ)/(2πR) [Hz], no surface tension (Minnaert 1933).
/// @param radius  equilibrium radius R [m], > 0
double basicMinnaertFrequency(double radius, const LiquidProperties& liquid);

/// @brief Ambient liquid pressure at the bubble [Pa]: p₀, or p₀ + ρgh with model.hydrostatic.
/// @param depth  distance h from the bubble centre to the free surface [m], ≥ 0
double ambientPressureAt(double depth, const LiquidProperties& liquid, const OscillatorModel& model);

/// @brief Equilibrium pressure of the gas in the bubble p_g0 = p_amb + 2σ/R (− p_v with vapour) [Pa].
double gasPressure(double radius, double ambientPressure, const LiquidProperties& liquid,
                   const OscillatorModel& model);

/// @brief Thermal diffusivity of the gas D_g = K_g/(ρ_g c_p,g), ρ_g = p_g M/(R_gas T) [m²/s].
/// @param gasPressure  p_g [Pa] at which the gas density is evaluated
double gasThermalDiffusivity(double gasPressure, const GasProperties& gas);

/// @brief Prosperetti's complex polytropic function
///        Φ(ω) = 3γ / (1 − 3(γ−1) iχ [√(i/χ) coth√(i/χ) − 1]),  χ = D_g/(ωR²).
///        κ_eff = Re Φ/3; the thermal loss is in Im Φ. Uses coth → 1 for large |√(i/χ)|.
/// @param angularFrequency  ω [rad/s], > 0
/// @param radius            R [m], > 0
/// @param gasPressure       p_g0 [Pa], where D_g is evaluated
std::complex<double> thermalPolytropicFunction(double angularFrequency, double radius,
                                               double gasPressure, const GasProperties& gas);

/// @brief Natural angular frequency ω₀ [rad/s] from the linearised Rayleigh–Plesset equation:
///        ω₀² = [3κ(p_amb − p_v + 2σ/R) − 2σ/R] / (ρR²), with κ = γ (Adiabatic) or
///        κ = Re Φ(ω₀)/3 (Thermal, solved by fixed-point iteration from the adiabatic ω₀).
///        Terms follow model.surfaceTension and model.vapour.
/// @param radius           R [m], > 0
/// @param ambientPressure  p_amb [Pa] (see ambientPressureAt)
/// @throws std::domain_error if the restoring pressure 3κ·p_g0 − 2σ/R is not positive
/// @throws std::runtime_error if the thermal fixed-point iteration does not converge
double naturalAngularFrequency(double radius, double ambientPressure,
                               const LiquidProperties& liquid, const OscillatorModel& model);

/// @brief naturalAngularFrequency / 2π [Hz].
double naturalFrequency(double radius, double ambientPressure, const LiquidProperties& liquid,
                        const OscillatorModel& model);

}  // namespace fluidsound::acoustics
