// acoustics/bubble/depth_shift.cpp — frequency factor of a bubble near a free surface or rigid wall:
// Strasberg's (1953) image formula and the exact sphere–plane capacitance series. docs/physics.md §5.
#include "acoustics/bubble/depth_shift.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fluidsound::acoustics {
namespace {

/// Relative size of a series term at which the capacitance sum stops (below 2^(−53) ≈ 1.1e-16).
constexpr double kCapacitanceTruncation = 1e-16;

/// Cap on the capacitance terms. Terms fall like e^(−nα), so about 37/α terms are needed;
/// 10⁶ terms reach α = 4e-5, i.e. h/R = 1 + 8e-10, in a few milliseconds.
constexpr long kMaxCapacitanceTerms = 1'000'000;

/// x = R/(2h) with h clamped to ≥ kMinimumDepthOverRadius·R (Strasberg 1953, docs/physics.md §5).
double strasbergParameter(double radius, double depth) {
  const double clampedDepth = std::max(depth, kMinimumDepthOverRadius * radius);
  return radius / (2.0 * clampedDepth);
}

/// √(C/C∞), C/C∞ = sinh α Σ_{n≥1} s_n / sinh(nα), cosh α = h/R, s_n = sign^(n+1)
/// (sign = +1 free surface, −1 rigid wall). docs/physics.md §5.
double exactCapacitanceRatio(double radius, double depth, double sign, const char* name) {
  if (!(radius > 0.0) || !(depth > radius)) {
    throw std::invalid_argument(std::string(name) + ": need depth > radius > 0, got depth " +
                                std::to_string(depth) + " m, radius " + std::to_string(radius) + " m");
  }
  // α = acosh(1 + d), d = (h − R)/R, written with log1p so that h ≈ R keeps its digits.
  const double d = (depth - radius) / radius;
  const double alpha = std::log1p(d + std::sqrt(d * (2.0 + d)));
  // 1/sinh(nα) = 2e^(−nα)/(1 − e^(−2nα)): no overflow of sinh for large n.
  double sum = 0.0;
  double coefficient = 1.0;  // s_n
  for (long n = 1; n <= kMaxCapacitanceTerms; ++n) {
    const double na = static_cast<double>(n) * alpha;
    const double term = coefficient * 2.0 * std::exp(-na) / -std::expm1(-2.0 * na);
    sum += term;
    if (std::abs(term) < kCapacitanceTruncation * std::abs(sum)) {
      return std::sqrt(std::sinh(alpha) * sum);
    }
    coefficient *= sign;
  }
  throw std::domain_error(std::string(name) + ": capacitance series did not converge for h/R = " +
                          std::to_string(depth / radius));
}

}  // namespace

// Strasberg 1953 (as coded in Langlois' 2016 demo): f(h)/f∞ = (1 − x − x⁴)^(−1/2). docs/physics.md §5.
double freeSurfaceFrequencyRatio(double radius, double depth) {
  return std::sqrt(freeSurfaceFrequencyRatioSquared(radius, depth));
}

double freeSurfaceFrequencyRatioSquared(double radius, double depth) {
  const double x = strasbergParameter(radius, depth);
  return 1.0 / (1.0 - x - x * x * x * x);
}

// Strasberg 1953: f(h)/f∞ = (1 + x − x⁴)^(−1/2). docs/physics.md §5.
double rigidWallFrequencyRatio(double radius, double depth) {
  const double x = strasbergParameter(radius, depth);
  return 1.0 / std::sqrt(1.0 + x - x * x * x * x);
}

// Langlois et al. 2016 (f ∝ √C) with the exact sphere–plane capacitance (Kelvin images).
// docs/physics.md §5.
double exactFreeSurfaceFrequencyRatio(double radius, double depth) {
  return exactCapacitanceRatio(radius, depth, 1.0, "exactFreeSurfaceFrequencyRatio");
}

double exactRigidWallFrequencyRatio(double radius, double depth) {
  return exactCapacitanceRatio(radius, depth, -1.0, "exactRigidWallFrequencyRatio");
}

}  // namespace fluidsound::acoustics
