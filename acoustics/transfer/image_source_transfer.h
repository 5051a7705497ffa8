// acoustics/transfer/image_source_transfer.h — transfer stage, analytic model: the pressure a listener
// receives from a bubble under a locally flat pressure-release surface (negative image source in
// water, evanescent-cone far field in air), relative to the bubble's free-field pressure at 1 m.
// docs/transfer.md; shared physics.md §6, table T4.
#pragma once

#include <array>

#include "acoustics/bubble/liquid_properties.h"
#include "sim/core/vec3.h"

namespace fluidsound::acoustics {

/// The free surface near one bubble, taken as a flat plane for one frame (the image-source model's
/// only assumption about geometry). A value type: the per-frame stage finds it, e.g. from the
/// liquid level set as surface point = bubble centre + depth·normal.
struct LocalSurface {
  Vec3 point{};        ///< the surface point above the bubble [m], world space
  Vec3 normal{};       ///< unit normal [-], pointing out of the liquid into the air
  double depth = 0.0;  ///< h [m], from the bubble centre up to the surface along normal, > 0
  bool operator==(const LocalSurface&) const = default;
};

/// @brief Half-angle θ_c = asin(c_a/c_w) [rad] of the cone, around the surface normal, into which
///        sound leaves the water as a propagating wave (13.39° for water and air at 20 °C).
/// @return π/2 if c_a ≥ c_w (no evanescent region)
double criticalAngle(const LiquidProperties& liquid, const AirProperties& air);

/// @brief Air far-field factor E(θ) [-] of a bubble at depth h under a flat pressure-release
///        surface: E = 1 inside the critical cone k_a sinθ ≤ k_w, E = exp(−h√(k_a² sin²θ − k_w²))
///        outside (evanescent), k_a = ω/c_a, k_w = ω/c_w. Shared physics.md §6, item 3 [derived].
/// @param angularFrequency  ω [rad/s], > 0
/// @param depth             h [m], bubble centre to the surface, > 0
/// @param angleFromNormal   θ [rad] in [0, π/2], listener direction from the surface normal
/// @throws std::invalid_argument for ω ≤ 0, h ≤ 0 or θ outside [0, π/2] (or any of them NaN)
double airFarFieldFactor(double angularFrequency, double depth, double angleFromNormal,
                         const LiquidProperties& liquid, const AirProperties& air);

/// @brief The incompressible-water limit (c_w → ∞, k_w → 0) of airFarFieldFactor:
///        E = exp(−k_a h sinθ) [-]. Shared physics.md §6, item 3; table T4 "E(90°) incompr.".
/// @param angularFrequency, depth, angleFromNormal  as airFarFieldFactor
/// @throws std::invalid_argument as airFarFieldFactor
double incompressibleAirFarFieldFactor(double angularFrequency, double depth,
                                       double angleFromNormal, const AirProperties& air);

/// @brief Transfer to a listener in air, far field: T = (2ρ_a/ρ_w)·(1 m/r)·E(θ) [-], the
///        listener's pressure ÷ the bubble's free-field pressure in water at 1 m, to leading order
///        in ρ_a/ρ_w. Shared physics.md §6, item 5 (T(1 m, 0°) = 2.4128×10⁻³).
/// @param distance  r [m], from the surface point above the bubble to the listener, > 0
/// @note Far field: at r = 1 m above a 10-mm-deep bubble the exact value is 4–7 % lower
///       (shared physics.md T5); the error falls like h√(k_a/r).
/// @throws std::invalid_argument for r ≤ 0, and as airFarFieldFactor
double airTransfer(double angularFrequency, double depth, double distance, double angleFromNormal,
                   const LiquidProperties& liquid, const AirProperties& air);

/// @brief Transfer to a listener in water, exact for a flat pressure-release surface: the bubble's
///        monopole minus its negative image at the mirror point,
///        |p|/|p_free(1 m)| = 1 m · |e^(−ik_w r₁)/r₁ − e^(−ik_w r₂)/r₂| [-],
///        r₁ to the bubble, r₂ to the image. Shared physics.md §6, "Listener in water" [derived].
/// @param depth               h [m], bubble centre to the surface, > 0
/// @param listenerDepth       z [m], listener to the surface (below it), ≥ 0; 0 gives 0
/// @param horizontalDistance  ρ [m], listener to the normal line through the bubble, ≥ 0
/// @throws std::invalid_argument for ω ≤ 0, h ≤ 0, z < 0, ρ < 0, or a listener at the bubble
///         centre (r₁ = 0)
double waterTransfer(double angularFrequency, double depth, double listenerDepth,
                     double horizontalDistance, const LiquidProperties& liquid);

/// @brief Far-field form of waterTransfer: 2|sin(k_w h cosθ)|·(1 m/r) [-], which tends to the
///        dipole 2k_w h cosθ·(1 m/r) for k_w h ≪ 1. Shared physics.md §6, "Listener in water";
///        T4 last column (θ = 0, r = 1 m).
/// @param distance         r [m], from the surface point above the bubble to the listener, > 0
/// @param angleFromNormal  θ [rad] in [0, π/2], from the downward normal (the vertical)
/// @throws std::invalid_argument for ω ≤ 0, h ≤ 0, r ≤ 0 or θ outside [0, π/2]
double waterFarFieldTransfer(double angularFrequency, double depth, double distance,
                             double angleFromNormal, const LiquidProperties& liquid);

/// @brief The transfer stage's per-bubble, per-listener value with the image-source model: the
///        amplitude (≥ 0) of the listener's pressure ÷ the bubble's free-field pressure at 1 m.
///        Listener side of the plane (point, normal): above (n·(x − point) > 0) → airTransfer;
///        on the plane → airTransfer (θ = 90°; the water-side value is 0 on a pressure-release
///        surface, the air side is the limit from above); below → waterTransfer (exact images).
///        All distances and angles are measured from surface.point along surface.normal.
/// @param bubbleCentre      [m], world space; must lie at surface.point − depth·normal within the
///                          geometry tolerance below (catches a normal pointing into the liquid)
/// @param surface           the local plane and the bubble's depth below it
/// @param listener          [m], world space
/// @param angularFrequency  ω [rad/s], > 0 (the bubble's, e.g. its depth-shifted natural frequency)
/// @throws std::invalid_argument for depth ≤ 0, |normal| not 1 within kUnitNormalTolerance, ω ≤ 0,
///         a non-finite coordinate, a bubble centre off surface.point − depth·normal, or a listener
///         at a singular point — the surface point (air, r = 0) or the bubble centre (water,
///         r₁ = 0) — where "at" means within the geometry tolerance below
double imageSourceTransferAmplitude(const Vec3& bubbleCentre, const LocalSurface& surface,
                                    const Vec3& listener, double angularFrequency,
                                    const LiquidProperties& liquid, const AirProperties& air);

/// Allowed | |normal| − 1 |: a normal normalised in float is unit to ~1e-7.
inline constexpr double kUnitNormalTolerance = 1e-6;

/// Geometry tolerance of imageSourceTransferAmplitude: allowed distance between the bubble centre
/// and surface.point − depth·normal, and distance from the surface point (air) or the bubble centre
/// (water) below which a listener counts as at that singular point: 0.1 % of the depth
/// (physics.md's tolerance for this model) plus 1e-7 m (float rounding of positions up to ~1 m).
inline constexpr double kGeometryRelativeTolerance = 1e-3;
inline constexpr double kGeometryAbsoluteTolerance = 1e-7;  // [m]

}  // namespace fluidsound::acoustics
