// acoustics/modal/hertz_contact.h — the elastic (Hertz) impact of two curved bodies: how long they
// touch, how hard, and what that does to the modes an impact excites (docs/solids.md, Contact).
// Sphere on a half-space, or two spheres by the effective radius (Johnson, "Contact Mechanics",
// 1985, §11.4; shared solids.md T5):
//   1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂,   1/R = 1/R₁ + 1/R₂,   1/m = 1/m₁ + 1/m₂,
//   F(δ) = (4/3)·E*·√R·δ^{3/2},   δ_max = (15·m·v² / (16·E*·√R))^{2/5},
//   t_c = 2·δ_max/v·∫₀¹ dx/√(1 − x^{5/2}) = 2.9432·δ_max/v = 2.868·(m²/(R·E*²·v))^{1/5}.
#pragma once

#include "acoustics/modal/solid_material.h"

namespace fluidsound::acoustics {

/// The effective contact modulus E* [Pa] of two materials.
double effectiveContactModulus(const SolidMaterial& a, const SolidMaterial& b);

/// One elastic impact at normal approach speed v.
struct HertzImpact {
  double duration;     ///< t_c [s]: from first touch to separation
  double peakForce;    ///< F_max [N]
  double indentation;  ///< δ_max [m]: the largest approach of the two bodies
};

/// @brief The Hertz impact of bodies of effective mass m [kg] and effective radius R [m] whose
///        contact modulus is E* [Pa], meeting at normal speed v [m/s] (all > 0).
/// @throws std::invalid_argument for a value that is not positive and finite
HertzImpact hertzImpact(double effectiveMass, double effectiveRadius, double contactModulus, double normalSpeed);

/// @brief How much of an impulse a mode of angular frequency ω [rad/s] receives from a half-sine
///        force pulse of duration t_c [s] (the Hertz force's usual stand-in), against an ideal
///        impulse at the pulse's centre: the pulse's spectrum referred to its centre over its
///        impulse, cos(ω·t_c/2) / (1 − (ω·t_c/π)²) — real, 1 at ω → 0, π/4 at ω = π/t_c (the
///        removable point), 0 at ω = 3π/t_c and negative (the mode rung in opposite phase) beyond.
///        Derived from ∫₀^{t_c} sin(πt/t_c)·e^{−iω(t − t_c/2)} dt = (2t_c/π)·cos(ωt_c/2)/(1 − (ωt_c/π)²)
///        (shared solids.md T5 gives its magnitude).
double halfSinePulseFactor(double angularFrequency, double duration);

}  // namespace fluidsound::acoustics
