// acoustics/bubble/oscillator_model.h — the choices that define a bubble oscillator (frequency, damping,
// excitation, chirp); defaults are those marked "default" in docs/physics.md.
#pragma once

namespace fluidsound::acoustics {

/// How the gas in the bubble is compressed.
enum class PolytropicModel {
  Adiabatic,  ///< κ = γ (Minnaert 1933; Harmonic Fluids). Default.
  Thermal,    ///< κ_eff = Re Φ(ω)/3 (Prosperetti 1977/1991, Devin 1959), solved self-consistently.
};

/// How the oscillation decays.
enum class DampingModel {
  Devin,       ///< δ = δ_rad + δ_vis + δ_th (Devin 1959 exact thermal term). Default.
  VanDenDoel,  ///< d = 0.13/r + 0.0072 r^(−3/2) s⁻¹ (van den Doel 2005), graphics formula.
};

/// How the bubble is set ringing at birth.
enum class ExcitationModel {
  NeckCollapseJet,      ///< Czerski & Deane (2010) neck-collapse forcing, as Langlois et al. 2016 Eq. 14. Default.
  InitialDisplacement,  ///< R = R₀(1 + ε) at birth.
};

/// Every modelling choice of the bubble oscillator, with documented defaults.
struct OscillatorModel {
  PolytropicModel polytropic = PolytropicModel::Adiabatic;
  bool surfaceTension = true;  ///< include the Laplace pressure 2σ/R (default on)
  bool vapour = false;         ///< include the vapour pressure p_v in the restoring term (default off)
  bool hydrostatic = false;    ///< ambient pressure p₀ + ρgh at the bubble's depth h (default off)
  DampingModel damping = DampingModel::Devin;
  ExcitationModel excitation = ExcitationModel::NeckCollapseJet;
  double initialDisplacement = 1e-3;  ///< ε [-], for ExcitationModel::InitialDisplacement
  double jetConeParameter = 0.84;     ///< η [-] = tan 40°, Czerski & Deane neck-collapse jet
  double jetMaxDuration = 0.6e-3;     ///< cap of the forcing time T_c [s] (Langlois et al. 2016)
  bool chirp = false;                 ///< van den Doel rising pitch f₀(1 + ξβt) (default off)
  double chirpRiseFactor = 0.1;       ///< ξ [-], van den Doel's rise factor
};

}  // namespace fluidsound::acoustics
