// acoustics/bubble/depth_shift.h — rise of a bubble's resonance frequency near a pressure-release free
// surface (and fall near a rigid wall): Strasberg (1953) image correction and the exact
// sphere–plane capacitance series. docs/physics.md §5.
#pragma once

namespace fluidsound::acoustics {

/// Depths below this multiple of the radius are clamped: Strasberg's formula is > 1 % low there
/// and singular at h = 0.69R, and a real bubble that close to the surface is not spherical.
inline constexpr double kMinimumDepthOverRadius = 1.25;

/// @brief Strasberg free-surface factor f(h)/f∞ = (1 − x − x⁴)^(−1/2), x = R/(2h).
/// @param radius  R [m], > 0
/// @param depth   h [m], bubble centre to the free surface; clamped to ≥ kMinimumDepthOverRadius·R
double freeSurfaceFrequencyRatio(double radius, double depth);

/// @brief The square of freeSurfaceFrequencyRatio, 1/(1 − x − x⁴), for code that needs ω² (one
///        square root fewer in the synthesizer's per-block work).
double freeSurfaceFrequencyRatioSquared(double radius, double depth);

/// @brief Strasberg rigid-wall factor f(h)/f∞ = (1 + x − x⁴)^(−1/2), x = R/(2h) (frequency falls).
/// @param depth  h [m], bubble centre to the wall; clamped like freeSurfaceFrequencyRatio
double rigidWallFrequencyRatio(double radius, double depth);

/// @brief Exact sphere–plane capacitance ratio √(C/C∞), C/C∞ = sinh α Σ_{n≥1} s_n / sinh(nα),
///        cosh α = h/R; s_n = 1 (free surface) or (−1)^(n+1) (rigid wall). Reference for tests.
/// @param depth  h [m] > R
/// @throws std::invalid_argument unless depth > radius > 0
/// @throws std::domain_error if the series does not converge (h/R within ~1e-9 of 1)
double exactFreeSurfaceFrequencyRatio(double radius, double depth);
double exactRigidWallFrequencyRatio(double radius, double depth);

}  // namespace fluidsound::acoustics
