// acoustics/transfer/image_source_transfer.cpp — image-source transfer from a bubble under a flat
// pressure-release surface to a listener in air or in water. docs/transfer.md; shared physics.md
// §6.
#include "acoustics/transfer/image_source_transfer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fluidsound::acoustics {
namespace {

/// The transfer convention's reference distance: free-field pressure in water at 1 m [m]
/// (DESIGN.md, bubble-track contract; shared physics.md §1).
constexpr double kReferenceDistance = 1.0;

/// A number for an error message, 6 significant digits (std::to_string would print 1e-9 as
/// 0.000000).
std::string show(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

[[noreturn]] void fail(const char* function, const std::string& what) {
  throw std::invalid_argument(std::string(function) + ": " + what);
}

/// Throws unless value > 0 (NaN fails too).
void requirePositive(const char* function, const char* quantity, double value, const char* unit) {
  if (!(value > 0.0)) {
    fail(function, std::string(quantity) + " = " + show(value) + " " + unit + " must be > 0");
  }
}

/// Throws unless value ≥ 0 (NaN fails too).
void requireNonNegative(const char* function, const char* quantity, double value,
                        const char* unit) {
  if (!(value >= 0.0)) {
    fail(function, std::string(quantity) + " = " + show(value) + " " + unit + " must be ≥ 0");
  }
}

/// Throws unless θ ∈ [0, π/2] (NaN fails too).
void requireAngle(const char* function, double angle) {
  if (!(angle >= 0.0 && angle <= 0.5 * std::numbers::pi)) {
    fail(function, "angle from the normal θ = " + show(angle) + " rad must be in [0, π/2]");
  }
}

/// E from sinθ (shared physics.md §6, item 3): 1 if k_a sinθ ≤ k_w, else
/// exp(−h√(k_a² sin²θ − k_w²)). The radicand is factored, (k_a sinθ − k_w)(k_a sinθ + k_w), so
/// that it keeps its digits at the cone edge, where E → 1 continuously.
double evanescentFactor(double airWavenumber, double waterWavenumber, double depth,
                        double sinAngle) {
  const double radicand =
      (airWavenumber * sinAngle - waterWavenumber) * (airWavenumber * sinAngle + waterWavenumber);
  if (radicand <= 0.0) return 1.0;
  return std::exp(-depth * std::sqrt(radicand));
}

/// 2ρ_a/ρ_w [-]: the on-axis air transfer at 1 m (shared physics.md §6, item 5).
double densityRatioFactor(const LiquidProperties& liquid, const AirProperties& air) {
  return 2.0 * air.density / liquid.density;
}

/// 1 m · |e^(−ik r₁)/r₁ − e^(−ik r₂)/r₂| with r₁ = √(ρ² + (z − h)²), r₂ = √(ρ² + (z + h)²).
/// |a e^(iα) − b e^(iβ)|² = (a − b)² + 4ab sin²((α − β)/2), and r₂ − r₁ = 4hz/(r₁ + r₂) (from
/// r₂² − r₁² = 4hz), so nothing cancels for k_w h ≪ 1 or a listener far away. Needs r₁ > 0.
double imagePairMagnitude(double wavenumber, double depth, double listenerDepth,
                          double horizontalDistance) {
  const double r1 = std::hypot(horizontalDistance, listenerDepth - depth);  // to the bubble [m]
  const double r2 = std::hypot(horizontalDistance, listenerDepth + depth);  // to the image [m]
  const double pathDifference = 4.0 * depth * listenerDepth / (r1 + r2);    // r₂ − r₁ [m]
  const double halfPhase = std::sin(0.5 * wavenumber * pathDifference);
  return kReferenceDistance *
         std::sqrt(pathDifference * pathDifference + 4.0 * r1 * r2 * halfPhase * halfPhase) /
         (r1 * r2);
}

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

bool finite(const Vec3& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

std::string show(const Vec3& a) {
  // Appended piece by piece: g++ 12 warns falsely (-Wrestrict) on "[" + std::string&&.
  std::string text = "[";
  text.append(show(a[0])).append(", ").append(show(a[1])).append(", ").append(show(a[2])).append("]");
  return text;
}

}  // namespace

// θ_c = asin(c_a/c_w): k_a sinθ = k_w at the cone edge (shared physics.md §6, item 3).
double criticalAngle(const LiquidProperties& liquid, const AirProperties& air) {
  const double ratio = air.soundSpeed / liquid.soundSpeed;
  return ratio >= 1.0 ? 0.5 * std::numbers::pi : std::asin(ratio);
}

// E(θ), shared physics.md §6, item 3 [derived; verified numerically there].
double airFarFieldFactor(double angularFrequency, double depth, double angleFromNormal,
                         const LiquidProperties& liquid, const AirProperties& air) {
  constexpr const char* kName = "airFarFieldFactor";
  requirePositive(kName, "angular frequency ω", angularFrequency, "rad/s");
  requirePositive(kName, "depth h", depth, "m");
  requireAngle(kName, angleFromNormal);
  return evanescentFactor(angularFrequency / air.soundSpeed, angularFrequency / liquid.soundSpeed,
                          depth, std::sin(angleFromNormal));
}

// Incompressible-water limit exp(−k_a h sinθ), shared physics.md §6, item 3.
double incompressibleAirFarFieldFactor(double angularFrequency, double depth,
                                       double angleFromNormal, const AirProperties& air) {
  constexpr const char* kName = "incompressibleAirFarFieldFactor";
  requirePositive(kName, "angular frequency ω", angularFrequency, "rad/s");
  requirePositive(kName, "depth h", depth, "m");
  requireAngle(kName, angleFromNormal);
  return std::exp(-(angularFrequency / air.soundSpeed) * depth * std::sin(angleFromNormal));
}

// T(r, θ) = (2ρ_a/ρ_w)(1 m/r) E(θ), shared physics.md §6, item 5.
double airTransfer(double angularFrequency, double depth, double distance, double angleFromNormal,
                   const LiquidProperties& liquid, const AirProperties& air) {
  requirePositive("airTransfer", "distance r", distance, "m");
  return densityRatioFactor(liquid, air) * (kReferenceDistance / distance) *
         airFarFieldFactor(angularFrequency, depth, angleFromNormal, liquid, air);
}

// p = p_mono(r₁) − p_mono(r₂), negative image at the mirror point, shared physics.md §6.
double waterTransfer(double angularFrequency, double depth, double listenerDepth,
                     double horizontalDistance, const LiquidProperties& liquid) {
  constexpr const char* kName = "waterTransfer";
  requirePositive(kName, "angular frequency ω", angularFrequency, "rad/s");
  requirePositive(kName, "depth h", depth, "m");
  requireNonNegative(kName, "listener depth z", listenerDepth, "m");
  requireNonNegative(kName, "horizontal distance ρ", horizontalDistance, "m");
  if (horizontalDistance == 0.0 && listenerDepth == depth) {
    fail(kName,
         "listener at the bubble centre (r₁ = 0): the free-field pressure is singular there");
  }
  return imagePairMagnitude(angularFrequency / liquid.soundSpeed, depth, listenerDepth,
                            horizontalDistance);
}

// Far field of the image pair: 2|sin(k_w h cosθ)|(1 m/r), shared physics.md §6.
double waterFarFieldTransfer(double angularFrequency, double depth, double distance,
                             double angleFromNormal, const LiquidProperties& liquid) {
  constexpr const char* kName = "waterFarFieldTransfer";
  requirePositive(kName, "angular frequency ω", angularFrequency, "rad/s");
  requirePositive(kName, "depth h", depth, "m");
  requirePositive(kName, "distance r", distance, "m");
  requireAngle(kName, angleFromNormal);
  const double waterWavenumber = angularFrequency / liquid.soundSpeed;
  return 2.0 * std::abs(std::sin(waterWavenumber * depth * std::cos(angleFromNormal))) *
         (kReferenceDistance / distance);
}

// Shared physics.md §6: air side items 3 and 5, water side the exact image pair. docs/transfer.md.
double imageSourceTransferAmplitude(const Vec3& bubbleCentre, const LocalSurface& surface,
                                    const Vec3& listener, double angularFrequency,
                                    const LiquidProperties& liquid, const AirProperties& air) {
  constexpr const char* kName = "imageSourceTransferAmplitude";
  requirePositive(kName, "angular frequency ω", angularFrequency, "rad/s");
  requirePositive(kName, "depth h", surface.depth, "m");
  if (!finite(bubbleCentre) || !finite(surface.point) || !finite(surface.normal) ||
      !finite(listener)) {
    fail(kName, "non-finite position or normal (bubble " + show(bubbleCentre) + ", surface point " +
                    show(surface.point) + ", normal " + show(surface.normal) + ", listener " +
                    show(listener) + ")");
  }
  const Vec3& n = surface.normal;
  const double normalLength = norm(n);
  if (!(std::abs(normalLength - 1.0) <= kUnitNormalTolerance)) {
    fail(kName, "surface normal " + show(n) + " has length " + show(normalLength) + ", expected 1");
  }
  const double h = surface.depth;
  const Vec3 expectedCentre = {surface.point[0] - h * n[0], surface.point[1] - h * n[1],
                               surface.point[2] - h * n[2]};
  const Vec3 offCentre = {bubbleCentre[0] - expectedCentre[0], bubbleCentre[1] - expectedCentre[1],
                          bubbleCentre[2] - expectedCentre[2]};
  const double tolerance = kGeometryRelativeTolerance * h + kGeometryAbsoluteTolerance;  // [m]
  const double mismatch = norm(offCentre);
  if (!(mismatch <= tolerance)) {
    fail(kName, "bubble centre " + show(bubbleCentre) + " m is " + show(mismatch) +
                    " m from surface point − depth·normal " + show(expectedCentre) +
                    " m (does the normal point out of the liquid?)");
  }

  // The listener seen from the surface point: height s along n, distance ρ from the normal line.
  const Vec3 d = {listener[0] - surface.point[0], listener[1] - surface.point[1],
                  listener[2] - surface.point[2]};
  const double height = dot(d, n);  // s [m], > 0 in air
  const Vec3 horizontal = {d[0] - height * n[0], d[1] - height * n[1], d[2] - height * n[2]};
  const double horizontalDistance = norm(horizontal);  // ρ [m]

  if (height >= 0.0) {                // air, or on the plane (θ = 90°, the limit from above)
    const double distance = norm(d);  // r [m]
    if (!(distance > tolerance)) {
      fail(kName, "listener " + show(listener) + " m is at the surface point (r = " +
                      show(distance) + " m): the far field is singular there");
    }
    const double sinAngle = std::min(1.0, horizontalDistance / distance);
    return densityRatioFactor(liquid, air) * (kReferenceDistance / distance) *
           evanescentFactor(angularFrequency / air.soundSpeed, angularFrequency / liquid.soundSpeed,
                            h, sinAngle);
  }
  const double listenerDepth = -height;  // z [m] > 0
  if (!(std::hypot(horizontalDistance, listenerDepth - h) > tolerance)) {
    fail(kName, "listener " + show(listener) + " m is at the bubble centre (r₁ = " +
                    show(std::hypot(horizontalDistance, listenerDepth - h)) +
                    " m): the free-field pressure is singular there");
  }
  return imagePairMagnitude(angularFrequency / liquid.soundSpeed, h, listenerDepth,
                            horizontalDistance);
}

}  // namespace fluidsound::acoustics
