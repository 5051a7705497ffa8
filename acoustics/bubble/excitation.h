// acoustics/bubble/excitation.h — how loudly a new bubble rings: Czerski & Deane (2010) neck-collapse jet
// forcing (as Langlois et al. 2016 Eq. 14) or an initial radial displacement. docs/physics.md §7.3.
#pragma once

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/bubble/oscillator_model.h"

namespace fluidsound::acoustics {

/// @brief Free-field pressure amplitude at 1 m [Pa] left by the neck-collapse forcing
///        F(t) = −9γσ η p_in0 √(1 + η²) t² / (4ρR³), 0 ≤ t ≤ T_c, T_c = min(jetMaxDuration, R/(6 m/s)),
///        p_in0 = p₀ + 2σ/R, acting on v̈ + ω₀²v = F/m, m = ρ/(4πR) (no damping during forcing):
///        |V| = |∫₀^T_c (F/m) e^(−iω₀t) dt| / ω₀, p(1 m) = ρω₀²|V|/(4π). Closed-form integral.
/// @param angularFrequency  ω₀ [rad/s]
/// @note p_in0 uses the surface ambient pressure p₀ and always includes 2σ/R (as Langlois et al.
///       2016 code it), whatever model.hydrostatic and model.surfaceTension say.
double jetExcitationAmplitude(double radius, double angularFrequency, const LiquidProperties& liquid,
                              const OscillatorModel& model);

/// @brief Free-field pressure amplitude at 1 m [Pa] of R = R₀(1 + ε): p = ρω₀²R₀³ε.
double displacementExcitationAmplitude(double radius, double angularFrequency, double displacement,
                                       const LiquidProperties& liquid);

/// @brief The amplitude [Pa at 1 m] of the model's ExcitationModel.
double excitationAmplitude(double radius, double angularFrequency, const LiquidProperties& liquid,
                           const OscillatorModel& model);

}  // namespace fluidsound::acoustics
