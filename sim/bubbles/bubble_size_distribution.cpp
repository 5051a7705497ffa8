// sim/bubbles/bubble_size_distribution.cpp — see bubble_size_distribution.h.
#include "sim/bubbles/bubble_size_distribution.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fluidsound::sim {

namespace {

/// Throws std::invalid_argument "<where>.<field> must be <expectation>, got <value>".
[[noreturn]] void rejectParameter(const char* where, const char* field, const char* expectation,
                                  double value) {
  std::ostringstream message;
  message << where << "." << field << " must be " << expectation << ", got " << value;
  throw std::invalid_argument(message.str());
}

void requirePositive(const char* where, const char* field, double value, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0))
    rejectParameter(where, field, (std::string("a finite number > 0 ") + unit).c_str(), value);
}

void requireBounds(const char* where, double minRadius, double maxRadius) {
  requirePositive(where, "minRadius", minRadius, "(metres)");
  requirePositive(where, "maxRadius", maxRadius, "(metres)");
  if (!(minRadius < maxRadius)) {
    std::ostringstream message;
    message << where << ".minRadius must be < maxRadius (" << maxRadius << " m), got " << minRadius;
    throw std::invalid_argument(message.str());
  }
}

/// (e^z − 1)/z, continuous (= 1) at z = 0.
double relativeExpm1(double z) { return z == 0.0 ? 1.0 : std::expm1(z) / z; }

/// ∫_{x0}^{x1} x^(−k) dx for 0 < x0 ≤ x1, written as x0^(1−k) · L · (e^((1−k)L) − 1)/((1−k)L)
/// with L = ln(x1/x0): the closed form of the power integral that stays exact as k → 1, where it
/// becomes ln(x1/x0).
double powerIntegral(double x0, double x1, double k) {
  const double logRatio = std::log(x1 / x0), e = 1.0 - k;
  return std::pow(x0, e) * logRatio * relativeExpm1(e * logRatio);
}

/// The x ∈ [x0, x1] with ∫_{x0}^{x} x'^(−k) dx' = t·∫_{x0}^{x1} x'^(−k) dx', t ∈ [0, 1]: the
/// inverse of powerIntegral. From x0^(1−k)(e^((1−k)y) − 1)/(1−k) = t·x0^(1−k)(e^((1−k)L) − 1)/(1−k)
/// with y = ln(x/x0): y = ln(1 + t(e^((1−k)L) − 1))/(1−k), or y = tL when k = 1.
double powerQuantile(double x0, double x1, double k, double t) {
  const double logRatio = std::log(x1 / x0), e = 1.0 - k;
  const double y = e == 0.0 ? t * logRatio : std::log1p(t * std::expm1(e * logRatio)) / e;
  return x0 * std::exp(y);
}

/// Standard normal cumulative distribution Φ(z) = ½ erfc(−z/√2) (exact identity; erfc keeps full
/// relative precision in the lower tail, where we evaluate it).
double normalCdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }

/// Standard normal density φ(z) = e^(−z²/2)/√(2π).
double normalDensity(double z) {
  return std::exp(-0.5 * z * z) * std::numbers::inv_sqrtpi / std::numbers::sqrt2;
}

/// Relative step below which the quantile solve stops: a few ulps of double.
constexpr double kQuantileTolerance = 4e-16;
/// Bisection alone halves [lowerZ, upperZ] (width < 80 for any bounds with representable mass)
/// to below 1e-15 in ~60 steps; 200 is a safe cap that Newton never reaches.
constexpr int kQuantileIterations = 200;

/// The z ∈ [lo, hi] with Φ(z) = p, where Φ(lo) ≤ p ≤ Φ(hi): Newton's method on ln Φ(z) − ln p
/// (nearly quadratic in the lower tail, so it converges in a few steps from anywhere), kept
/// inside a shrinking bracket and replaced by bisection whenever a step leaves it or Φ
/// underflows.
double normalQuantileInBracket(double p, double lo, double hi) {
  if (!(p > 0.0)) return lo;
  double z = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < kQuantileIterations; ++iteration) {
    const double cdf = normalCdf(z);
    if (cdf < p)
      lo = z;
    else
      hi = z;
    double next = z - (std::log(cdf) - std::log(p)) * cdf / normalDensity(z);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool converged = std::abs(next - z) <= kQuantileTolerance * std::max(1.0, std::abs(z));
    z = next;
    if (converged || hi - lo <= kQuantileTolerance * std::max(1.0, std::abs(z))) break;
  }
  return z;
}

}  // namespace

BubbleSizeSampler::BubbleSizeSampler(const BubbleSizeDistribution& distribution)
    : distribution_(distribution) {
  if (const auto* p = std::get_if<PowerLawBubbleSizes>(&distribution_)) {
    constexpr const char* kWhere = "PowerLawBubbleSizes";
    requireBounds(kWhere, p->minRadius, p->maxRadius);
    requirePositive(kWhere, "hinzeRadius", p->hinzeRadius, "(metres)");
    if (!std::isfinite(p->smallExponent))
      rejectParameter(kWhere, "smallExponent", "a finite number", p->smallExponent);
    if (!std::isfinite(p->largeExponent))
      rejectParameter(kWhere, "largeExponent", "a finite number", p->largeExponent);
    // Number density normalised to N(a_H) = 1, radii in units of a_H: the two laws meet
    // continuously at a_H (Deane & Stokes 2002; physics.md §7.2 "continuous piecewise law").
    const double h = p->hinzeRadius;
    split_ = std::clamp(h, p->minRadius, p->maxRadius);
    lowerMass_ = powerIntegral(p->minRadius / h, split_ / h, p->smallExponent);
    upperMass_ = powerIntegral(split_ / h, p->maxRadius / h, p->largeExponent);
    const double total = lowerMass_ + upperMass_;
    if (!(std::isfinite(total) && total > 0.0))
      rejectParameter(kWhere, "exponents", "such that the number of bubbles in range is finite",
                      total);
    lowerFraction_ = lowerMass_ / total;
  } else {
    const auto& g = std::get<GaussianBubbleSizes>(distribution_);
    constexpr const char* kWhere = "GaussianBubbleSizes";
    requireBounds(kWhere, g.minRadius, g.maxRadius);
    requirePositive(kWhere, "meanRadius", g.meanRadius, "(metres)");
    requirePositive(kWhere, "radiusDeviation", g.radiusDeviation, "(metres)");
    const double zMin = (g.minRadius - g.meanRadius) / g.radiusDeviation;
    const double zMax = (g.maxRadius - g.meanRadius) / g.radiusDeviation;
    // Φ is exact (relative) in the lower tail only: when the bounds' centre lies above the mean,
    // sample −z on [−zMax, −zMin] instead (the normal is symmetric).
    reflected_ = zMin + zMax > 0.0;
    lowerZ_ = reflected_ ? -zMax : zMin;
    upperZ_ = reflected_ ? -zMin : zMax;
    lowerCdf_ = normalCdf(lowerZ_);
    upperCdf_ = normalCdf(upperZ_);
    if (!(upperCdf_ > lowerCdf_)) {
      std::ostringstream message;
      message << kWhere << ": no probability mass between minRadius (" << g.minRadius
              << " m) and maxRadius (" << g.maxRadius << " m) for meanRadius " << g.meanRadius
              << " m and radiusDeviation " << g.radiusDeviation << " m";
      throw std::invalid_argument(message.str());
    }
  }
}

double BubbleSizeSampler::radius(double uniform) const {
  if (!(uniform >= 0.0 && uniform <= 1.0)) {
    std::ostringstream message;
    message << "BubbleSizeSampler::radius: uniform variate must be in [0, 1], got " << uniform;
    throw std::invalid_argument(message.str());
  }
  if (const auto* p = std::get_if<PowerLawBubbleSizes>(&distribution_)) {
    // The ends exactly, not within the rounding of the inverse.
    if (uniform == 0.0) return p->minRadius;
    if (uniform == 1.0) return p->maxRadius;
    return powerLawRadius(*p, uniform);
  }
  const auto& g = std::get<GaussianBubbleSizes>(distribution_);
  if (uniform == 0.0) return g.minRadius;
  if (uniform == 1.0) return g.maxRadius;
  return gaussianRadius(g, uniform);
}

double BubbleSizeSampler::powerLawRadius(const PowerLawBubbleSizes& p, double uniform) const {
  // Inverse transform (Devroye 1986, Non-Uniform Random Variate Generation, ch. II §2): pick
  // the segment by its number fraction, then invert its cumulative integral exactly.
  const double h = p.hinzeRadius;
  double a;
  if (uniform < lowerFraction_) {
    a = h * powerQuantile(p.minRadius / h, split_ / h, p.smallExponent, uniform / lowerFraction_);
  } else if (upperMass_ > 0.0) {
    const double t = (uniform - lowerFraction_) / (1.0 - lowerFraction_);
    a = h * powerQuantile(split_ / h, p.maxRadius / h, p.largeExponent, std::min(t, 1.0));
  } else {
    a = p.maxRadius;  // uniform = 1 with the whole range below a_H
  }
  // Rounding of exp/log may step an ulp outside the bounds.
  return std::clamp(a, p.minRadius, p.maxRadius);
}

double BubbleSizeSampler::gaussianRadius(const GaussianBubbleSizes& g, double uniform) const {
  // Truncated normal by inversion: z = Φ⁻¹(Φ(z_min) + u(Φ(z_max) − Φ(z_min))), radius μ + σz.
  // Reflected: the variate 1 − u on the mirrored bounds, so the radius still grows with u.
  const double u = reflected_ ? 1.0 - uniform : uniform;
  const double z =
      normalQuantileInBracket(lowerCdf_ + u * (upperCdf_ - lowerCdf_), lowerZ_, upperZ_);
  const double a = g.meanRadius + g.radiusDeviation * (reflected_ ? -z : z);
  return std::clamp(a, g.minRadius, g.maxRadius);
}

double BubbleSizeSampler::cumulativeFraction(double a) const {
  if (const auto* p = std::get_if<PowerLawBubbleSizes>(&distribution_)) {
    if (!(a > p->minRadius)) return 0.0;
    if (a >= p->maxRadius) return 1.0;
    const double h = p->hinzeRadius, total = lowerMass_ + upperMass_;
    if (a <= split_) return powerIntegral(p->minRadius / h, a / h, p->smallExponent) / total;
    return (lowerMass_ + powerIntegral(split_ / h, a / h, p->largeExponent)) / total;
  }
  const auto& g = std::get<GaussianBubbleSizes>(distribution_);
  if (!(a > g.minRadius)) return 0.0;
  if (a >= g.maxRadius) return 1.0;
  const double z = (a - g.meanRadius) / g.radiusDeviation, mass = upperCdf_ - lowerCdf_;
  // Reflected: the fraction above a is the mirrored fraction below −z.
  return reflected_ ? (upperCdf_ - normalCdf(-z)) / mass : (normalCdf(z) - lowerCdf_) / mass;
}

double fractionBelowHinzeRadius(const PowerLawBubbleSizes& sizes) {
  return BubbleSizeSampler(sizes).cumulativeFraction(sizes.hinzeRadius);
}

}  // namespace fluidsound::sim
