// sim/bubbles/bubble_size_distribution.h — bubble model: the radius of each new bubble, drawn from a size
// distribution by the exact inverse of its cumulative distribution, for a uniform variate that the
// caller takes from its own seeded stream (so the radii are as deterministic as that stream).
#pragma once

#include <variant>

namespace fluidsound::sim {

/// @brief Deane & Stokes (2002, Nature 418:839) breaking-wave bubble sizes: a continuous piecewise
///        power law of the number density, N(a) ∝ a^(−3/2) below the Hinze scale a_H and
///        ∝ a^(−10/3) above it, on [minRadius, maxRadius] (physics.md §7.2; the exponents and
///        a_H are tagged [memory] there, a_H = 0.7–1.7 mm per Deane, Stokes & Callaghan 2016).
/// @note  a_H may lie outside the range: then the whole range follows one of the two laws.
struct PowerLawBubbleSizes {
  double minRadius = 1.0e-4;    ///< a_min [m], > 0 (physics.md §7.2: 0.1 mm)
  double maxRadius = 5.0e-3;    ///< a_max [m], > a_min (physics.md §7.2: 5 mm)
  double hinzeRadius = 1.0e-3;  ///< a_H [m], > 0 (physics.md §7.2 default: 1 mm)
  double smallExponent = 1.5;   ///< N ∝ a^(−smallExponent) for a < a_H (Deane & Stokes: 3/2)
  double largeExponent = 10.0 / 3.0;  ///< N ∝ a^(−largeExponent) for a > a_H (Deane & Stokes: 10/3)
  bool operator==(const PowerLawBubbleSizes&) const = default;
};

/// @brief A normal distribution of radii truncated to [minRadius, maxRadius], the selectable
///        alternative of Harmonic Fluids (Zheng & James 2009) [memory: its section and values were
///        not checked], so mean and deviation have no defaults: 0 is rejected, the caller chooses.
struct GaussianBubbleSizes {
  double meanRadius = 0.0;       ///< μ [m], > 0 (may lie outside the bounds)
  double radiusDeviation = 0.0;  ///< σ [m], > 0
  double minRadius = 1.0e-4;     ///< [m], > 0 (physics.md §7.2: 0.1 mm)
  double maxRadius = 5.0e-3;     ///< [m], > minRadius (physics.md §7.2: 5 mm)
  bool operator==(const GaussianBubbleSizes&) const = default;
};

/// The closed set of size distributions.
using BubbleSizeDistribution = std::variant<PowerLawBubbleSizes, GaussianBubbleSizes>;

/// @brief Draws bubble radii from a validated size distribution by inverse transform sampling.
///        Holds the distribution's normalisation (segment masses, truncated-normal bounds) so a
///        draw costs a few transcendental calls (power law) or a bracketed Newton solve (Gaussian).
/// @par Example
/// @code
///   const BubbleSizeSampler sizes{PowerLawBubbleSizes{}};
///   const double radius = sizes.radius(uniformVariate);  // [m], uniformVariate ∈ [0, 1)
/// @endcode
class BubbleSizeSampler {
 public:
  /// @throws std::invalid_argument naming the parameter for a non-finite value, a radius ≤ 0,
  ///         minRadius ≥ maxRadius, a deviation ≤ 0, or a Gaussian with no probability mass
  ///         representable in double between the bounds.
  explicit BubbleSizeSampler(const BubbleSizeDistribution& distribution);

  /// @brief The radius [m] whose cumulative fraction is `uniform`: non-decreasing in `uniform`,
  ///        minRadius at 0, maxRadius at 1, always inside [minRadius, maxRadius].
  /// @param uniform  a variate of the caller's seeded stream, in [0, 1]
  /// @throws std::invalid_argument when `uniform` is outside [0, 1] or NaN
  double radius(double uniform) const;

  /// @brief Fraction of bubbles (by number) with radius ≤ `radius` [m]; 0 below minRadius,
  ///        1 above maxRadius. The analytic counterpart of radius().
  double cumulativeFraction(double radius) const;

  const BubbleSizeDistribution& distribution() const { return distribution_; }

 private:
  double powerLawRadius(const PowerLawBubbleSizes& p, double uniform) const;
  double gaussianRadius(const GaussianBubbleSizes& g, double uniform) const;

  BubbleSizeDistribution distribution_;
  // Power law, in units of a_H: [min, split] follows the small exponent, [split, max] the large.
  double split_ = 0.0;          ///< clamp(a_H, a_min, a_max) [m]
  double lowerMass_ = 0.0;      ///< ∫ N over [a_min, split], N(a_H) = 1, a in units of a_H
  double upperMass_ = 0.0;      ///< ∫ N over [split, a_max], same units
  double lowerFraction_ = 0.0;  ///< lowerMass_ / (lowerMass_ + upperMass_)
  // Truncated normal in standard units z = (a − μ)/σ, reflected (z → −z) when the bounds lie
  // mostly above the mean so that Φ is always evaluated where it has full relative precision.
  bool reflected_ = false;
  double lowerZ_ = 0.0, upperZ_ = 0.0;      ///< bounds in (possibly reflected) standard units
  double lowerCdf_ = 0.0, upperCdf_ = 0.0;  ///< Φ at those bounds
};

/// @brief Fraction (by number) of a power-law distribution below its Hinze radius, analytic:
///        91.18 % for the defaults (physics.md §7.2); 0 or 1 when a_H lies outside the range.
/// @throws std::invalid_argument as BubbleSizeSampler's constructor
double fractionBelowHinzeRadius(const PowerLawBubbleSizes& sizes);

}  // namespace fluidsound::sim
