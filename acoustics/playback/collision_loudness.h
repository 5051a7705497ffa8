// acoustics/playback/collision_loudness.h — how loud a recorded collision sound plays: the
// sample-playback paper's conservative-oscillator model (shared solids.md §1.4). An impact's
// pressure goes as v_n·√m_eff (the oscillator's amplitude v_n·√(m_eff/k); k and the radiation
// factor cancel against the recording's), a slide's and a roll's amplitude as the square root of
// the power they dissipate, √(F_n·v_t) and √(F_n·ω_t). A recording is made at the loudest its
// pair produces, so the gains are attenuations, never boosts.
#pragma once

namespace fluidsound::acoustics {

/// @brief Gain [dB, ≤ 0] of an impact at normal speed v [m/s] between bodies of reduced mass m
///        [kg] against the recording's v₀, m₀: ΔV = −20·log10(v₀√m₀ / (v√m)) (eq. 8), clamped to 0.
double impactGainDb(double normalSpeed, double reducedMass, double referenceSpeed, double referenceMass);

/// @brief Gain [dB, ≤ 0] of a slide (normal force F_n [N] × sliding speed v_t [m/s]) or a roll
///        (F_n × rolling rate ω_t [rad/s]) against its recording's: ΔV = −20·log10(√(P₀/P)) with
///        P = F_n·v (eq. 9), clamped to 0.
double rubbingGainDb(double normalForce, double speed, double referenceNormalForce, double referenceSpeed);

/// @brief The reduced mass m₁m₂/(m₁ + m₂) [kg] (eq. 3); a static body's mass is infinite: pass 0
///        for it, and the other's mass is returned.
double reducedMass(double mass1, double mass2);

}  // namespace fluidsound::acoustics
