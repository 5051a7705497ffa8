// acoustics/modal/hertz_contact.cpp — see hertz_contact.h.
#include "acoustics/modal/hertz_contact.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fluidsound::acoustics {
namespace {

/// 2·∫₀¹ dx/√(1 − x^{5/2}): the contact time in units of δ_max/v (Johnson 1985, eq. 11.24;
/// 2·B(2/5, 1/2)/(5/2) = 2.9432).
constexpr double kContactTimeFactor = 2.9432;

}  // namespace

double effectiveContactModulus(const SolidMaterial& a, const SolidMaterial& b) {
  return 1.0 / ((1.0 - a.poissonsRatio * a.poissonsRatio) / a.youngsModulus +
                (1.0 - b.poissonsRatio * b.poissonsRatio) / b.youngsModulus);
}

HertzImpact hertzImpact(double effectiveMass, double effectiveRadius, double contactModulus, double normalSpeed) {
  for (double value : {effectiveMass, effectiveRadius, contactModulus, normalSpeed})
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument("hertzImpact: mass, radius, modulus and speed must be positive and finite");
  const double rootR = std::sqrt(effectiveRadius);
  HertzImpact impact{};
  impact.indentation = std::pow(15.0 * effectiveMass * normalSpeed * normalSpeed / (16.0 * contactModulus * rootR), 0.4);
  impact.peakForce = 4.0 / 3.0 * contactModulus * rootR * std::pow(impact.indentation, 1.5);
  impact.duration = kContactTimeFactor * impact.indentation / normalSpeed;
  return impact;
}

double halfSinePulseFactor(double angularFrequency, double duration) {
  const double x = angularFrequency * duration / std::numbers::pi;  // ω·t_c/π
  const double denominator = 1.0 - x * x;
  if (std::abs(denominator) < 1e-6) return std::numbers::pi / 4.0;  // the limit at ω·t_c = π
  return std::cos(0.5 * angularFrequency * duration) / denominator;
}

}  // namespace fluidsound::acoustics
