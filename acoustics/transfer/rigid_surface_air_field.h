// acoustics/transfer/rigid_surface_air_field.h — the geometric transfer's air side, first model
// (shared transfer.md §1, item 1): the pressure p_L on the liquid surface from a unit
// volume-velocity source at the listener, the surface rigid (water is ~3600× stiffer than air) and
// nothing else in the way, so the surface doubles the free field; and the conversion of the
// water-side value u at a bubble into the project's transfer. docs/transfer.md.
#pragma once

#include <complex>

#include "acoustics/bubble/liquid_properties.h"
#include "sim/core/vec3.h"

namespace fluidsound::acoustics {

/// @brief The free field of a unit volume-velocity monopole at `source`: iωρ_a e^{−ik_a R}/(4πR)
///        [Pa per m³/s], R = |point − source|, e^{+iωt}; 0 when R = 0.
std::complex<double> freeFieldAirPressure(const Vec3& point, const Vec3& source,
                                          double angularFrequency, const AirProperties& air);

/// @brief p_L(y) = iωρ_a e^{−ik_a R} / (2πR) [Pa per m³/s], R = |y − listener|, k_a = ω/c_a:
///        twice the free field of a unit-Q monopole at the listener (rigid-surface doubling).
/// @param angularFrequency  ω [rad/s], > 0
/// @return 0 when R = 0 (the caller keeps listeners off the surface)
std::complex<double> rigidSurfaceAirPressure(const Vec3& surfacePoint, const Vec3& listener,
                                             double angularFrequency, const AirProperties& air);

/// @brief The transfer T = |u(x_b)| · 4π / (ωρ_w) · 1 m [-] from the water-side solution u at the
///        bubble (shared transfer.md §1: the listener's pressure per unit Q at the bubble, divided
///        by the bubble's free-field pressure at 1 m per unit Q, iωρ_w/(4π)).
double transferFromReciprocalPressure(std::complex<double> u, double angularFrequency,
                                      const LiquidProperties& liquid);

}  // namespace fluidsound::acoustics
