// tests/sim/bubbles/bubble_size_distribution_test.cpp — the bubble radius sampler: the Deane & Stokes
// (2002) power-law slopes by the sampler test of physics.md §7.2, its analytic 91.18 % below the
// Hinze scale, truncated-normal moments against closed forms, bounds, determinism and validation.
#include "sim/bubbles/bubble_size_distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace fluidsound::sim {
namespace {

constexpr int kSamples = 100000;  // N = 10⁵ (physics.md §7.2 sampler test)
constexpr std::uint64_t kSeed = 20020829;

/// A uniform double in [0, 1) from the top 53 bits of a 64-bit Mersenne Twister: the stream the
/// caller owns (fixed seed → fixed sequence on every platform; std::mt19937_64 is fully specified).
class UniformStream {
 public:
  explicit UniformStream(std::uint64_t seed) : engine_(seed) {}
  double next() { return std::ldexp(static_cast<double>(engine_() >> 11), -53); }

 private:
  std::mt19937_64 engine_;
};

std::vector<double> drawRadii(const BubbleSizeSampler& sampler, std::uint64_t seed, int count) {
  UniformStream uniform(seed);
  std::vector<double> radii(static_cast<std::size_t>(count));
  for (double& r : radii) r = sampler.radius(uniform.next());
  return radii;
}

/// Least-squares slope of log(density) against log(radius) over `bins` log-spaced bins of
/// [lo, hi]; density = count / bin width, placed at the bin's geometric centre. For an exact
/// power law a^(−k) the expected bin averages scale exactly as centre^(−k) (log bins are
/// self-similar), so the expected slope is −k with no binning bias.
double logLogSlope(const std::vector<double>& radii, double lo, double hi, int bins) {
  const double logLo = std::log(lo), step = (std::log(hi) - logLo) / bins;
  std::vector<double> counts(static_cast<std::size_t>(bins), 0.0);
  for (double r : radii) {
    if (r < lo || r >= hi) continue;
    const int b = std::min(bins - 1, static_cast<int>((std::log(r) - logLo) / step));
    counts[static_cast<std::size_t>(b)] += 1.0;
  }
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int b = 0; b < bins; ++b) {
    const double left = std::exp(logLo + b * step), right = std::exp(logLo + (b + 1) * step);
    const double x = logLo + (b + 0.5) * step;
    const double y = std::log(counts[static_cast<std::size_t>(b)] / (right - left));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (bins * sxy - sx * sy) / (bins * sxx - sx * sx);
}

TEST(BubbleSizeDistribution, PowerLawSlopesMatchDeaneAndStokes) {
  // Claim: radii from the default power law follow N(a) ∝ a^(−3/2) on 0.1–1 mm and ∝ a^(−10/3)
  // on 1–5 mm. Reference: Deane & Stokes 2002, protocol and tolerances of physics.md §7.2 (N =
  // 10⁵, 10 log bins per segment, least-squares log-log line): ±0.05 below, ±0.2 above, i.e.
  // 10 and 4 times the slopes' standard deviations over trials (0.005, 0.05) found there.
  const BubbleSizeSampler sampler{PowerLawBubbleSizes{}};
  const std::vector<double> radii = drawRadii(sampler, kSeed, kSamples);
  const double below = logLogSlope(radii, 1e-4, 1e-3, 10);
  const double above = logLogSlope(radii, 1e-3, 5e-3, 10);
  EXPECT_NEAR(below, -1.5, 0.05) << "slope below a_H";
  EXPECT_NEAR(above, -10.0 / 3.0, 0.2) << "slope above a_H";
  std::cout << "[ measured ] slope below " << below << " (ref −1.5), above " << above
            << " (ref −3.333)\n";
}

TEST(BubbleSizeDistribution, NinetyOnePercentLieBelowTheHinzeScale) {
  // Claim: 91.18 % of the bubbles (by number) of the default law lie below a_H = 1 mm.
  // Reference: physics.md §7.2 (4 digits), and the closed form ∫a^(−3/2) over 0.1–1 and a^(−10/3)
  // over 1–5 (mm, continuous at 1): 2(√10 − 1) / (2(√10 − 1) + (3/7)(1 − 5^(−7/3))).
  // Tolerance: analytic 5e-5 (the table's rounding); sampled: 4 binomial standard errors
  // √(p(1 − p)/N) ≈ 9e-4 each.
  const double closedForm =
      2.0 * (std::sqrt(10.0) - 1.0) /
      (2.0 * (std::sqrt(10.0) - 1.0) + 3.0 / 7.0 * (1.0 - std::pow(5.0, -7.0 / 3.0)));
  const double analytic = fractionBelowHinzeRadius(PowerLawBubbleSizes{});
  EXPECT_NEAR(analytic, 0.9118, 5e-5);
  EXPECT_NEAR(analytic, closedForm, 1e-14);

  const BubbleSizeSampler sampler{PowerLawBubbleSizes{}};
  const std::vector<double> radii = drawRadii(sampler, kSeed + 1, kSamples);
  int below = 0;
  for (double r : radii) below += r < 1e-3 ? 1 : 0;
  const double sampled = static_cast<double>(below) / kSamples;
  const double standardError = std::sqrt(analytic * (1.0 - analytic) / kSamples);
  EXPECT_NEAR(sampled, analytic, 4.0 * standardError);
  std::cout << "[ measured ] fraction below a_H: sampled " << sampled << ", analytic " << analytic
            << " (ref 0.9118)\n";
}

TEST(BubbleSizeDistribution, HinzeScaleOutsideTheRangeGivesASingleLaw) {
  // Claim: with a_H above a_max the whole range follows a^(−3/2) (fraction below a_H = 1); with
  // a_H below a_min it follows a^(−10/3) (fraction 0). Reference: the definition (continuous law,
  // one segment empty). Tolerance: slopes as in physics.md §7.2 for the same N (±0.05 for −3/2;
  // ±0.2 for −10/3, whose upper bins are sparse).
  PowerLawBubbleSizes small;
  small.hinzeRadius = 1e-2;
  PowerLawBubbleSizes large;
  large.hinzeRadius = 5e-5;
  EXPECT_EQ(fractionBelowHinzeRadius(small), 1.0);
  EXPECT_EQ(fractionBelowHinzeRadius(large), 0.0);
  const std::vector<double> a = drawRadii(BubbleSizeSampler{small}, kSeed + 2, kSamples);
  const std::vector<double> b = drawRadii(BubbleSizeSampler{large}, kSeed + 3, kSamples);
  EXPECT_NEAR(logLogSlope(a, 1e-4, 5e-3, 20), -1.5, 0.05);
  EXPECT_NEAR(logLogSlope(b, 1e-4, 1e-3, 10), -10.0 / 3.0, 0.2);
}

TEST(BubbleSizeDistribution, SamplerInvertsItsCumulativeFraction) {
  // Claim: radius() is the exact inverse of cumulativeFraction(): F(radius(u)) = u, for both
  // laws, including exponent 1 (where the power integral becomes a logarithm). Reference:
  // identity. Tolerance: 1e-12, rounding of a few exp/log/erfc evaluations.
  PowerLawBubbleSizes logUniform;
  logUniform.smallExponent = 1.0;
  GaussianBubbleSizes gaussian;
  gaussian.meanRadius = 1e-3;
  gaussian.radiusDeviation = 1e-3;
  for (const BubbleSizeDistribution& d :
       std::vector<BubbleSizeDistribution>{PowerLawBubbleSizes{}, logUniform, gaussian}) {
    const BubbleSizeSampler sampler{d};
    for (double u = 0.0; u <= 1.0; u += 1.0 / 64)
      EXPECT_NEAR(sampler.cumulativeFraction(sampler.radius(u)), u, 1e-12) << "u = " << u;
  }
}

/// Mean and standard deviation of a normal N(μ, σ²) truncated to [lo, hi] (closed form, e.g.
/// Johnson, Kotz & Balakrishnan 1994, §10.1): with α = (lo − μ)/σ, β = (hi − μ)/σ,
/// Z = Φ(β) − Φ(α): mean = μ + σ(φ(α) − φ(β))/Z,
/// variance = σ²[1 + (αφ(α) − βφ(β))/Z − ((φ(α) − φ(β))/Z)²].
struct Moments {
  double mean, deviation;
};
Moments truncatedNormalMoments(double mu, double sigma, double lo, double hi) {
  const auto pdf = [](double z) {
    return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
  };
  const auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); };
  const double a = (lo - mu) / sigma, b = (hi - mu) / sigma, z = cdf(b) - cdf(a);
  const double shift = (pdf(a) - pdf(b)) / z;
  return {mu + sigma * shift,
          sigma * std::sqrt(1.0 + (a * pdf(a) - b * pdf(b)) / z - shift * shift)};
}

TEST(BubbleSizeDistribution, GaussianMomentsMatchTheTruncatedNormal) {
  // Claim: Gaussian radii have the mean and standard deviation of the truncated normal, both when
  // the truncation is negligible (μ = 2 mm, σ = 0.4 mm: bounds 4.75σ and 7.5σ away) and when it
  // is heavy (μ = 1 mm, σ = 1 mm: lower bound at −0.9σ) — both through the sampler's reflected
  // branch — and when the mean lies above the upper bound (μ = 6 mm, σ = 1 mm, direct). Reference:
  // closed-form truncated-normal moments (truncatedNormalMoments). Tolerance: 4 standard errors of
  // N = 10⁵ samples — mean: s/√N; deviation: s/√(2N) for a normal, doubled to cover the truncated
  // shapes' kurtosis.
  struct Case {
    double mean, deviation;
  };
  for (const Case c : {Case{2e-3, 0.4e-3}, Case{1e-3, 1e-3}, Case{6e-3, 1e-3}}) {
    GaussianBubbleSizes g;
    g.meanRadius = c.mean;
    g.radiusDeviation = c.deviation;
    const std::vector<double> radii = drawRadii(BubbleSizeSampler{g}, kSeed + 4, kSamples);
    double sum = 0.0, sumSquares = 0.0;
    for (double r : radii) sum += r;
    const double mean = sum / kSamples;
    for (double r : radii) sumSquares += (r - mean) * (r - mean);
    const double deviation = std::sqrt(sumSquares / (kSamples - 1));
    const Moments expected = truncatedNormalMoments(c.mean, c.deviation, g.minRadius, g.maxRadius);
    EXPECT_NEAR(mean, expected.mean, 4.0 * expected.deviation / std::sqrt(kSamples))
        << "μ = " << c.mean << ", σ = " << c.deviation;
    EXPECT_NEAR(deviation, expected.deviation,
                4.0 * 2.0 * expected.deviation / std::sqrt(2.0 * kSamples))
        << "μ = " << c.mean << ", σ = " << c.deviation;
    std::cout << "[ measured ] μ " << c.mean << " σ " << c.deviation << ": sample mean " << mean
              << " (ref " << expected.mean << "), sd " << deviation << " (ref "
              << expected.deviation << ")\n";
  }
}

TEST(BubbleSizeDistribution, EverySampleLiesInsideTheBounds) {
  // Claim: radii never leave [a_min, a_max], at the ends of the variate range (0 and the largest
  // double below 1) or anywhere in 10⁵ draws, and grow with the variate. Reference: definition.
  // Tolerance: exact.
  GaussianBubbleSizes g;
  g.meanRadius = 1e-3;
  g.radiusDeviation = 2e-3;
  for (const BubbleSizeDistribution& d :
       std::vector<BubbleSizeDistribution>{PowerLawBubbleSizes{}, g}) {
    const BubbleSizeSampler sampler{d};
    const double lo = 1e-4, hi = 5e-3;
    EXPECT_EQ(sampler.radius(0.0), lo);
    EXPECT_EQ(sampler.radius(1.0), hi);
    EXPECT_LE(sampler.radius(std::nextafter(1.0, 0.0)), hi);
    double previous = 0.0;
    for (double u = 0.0; u < 1.0; u += 1.0 / 1024) {
      const double r = sampler.radius(u);
      EXPECT_GE(r, previous) << "u = " << u;
      previous = r;
    }
    for (double r : drawRadii(sampler, kSeed + 5, kSamples)) {
      ASSERT_GE(r, lo);
      ASSERT_LE(r, hi);
    }
  }
}

TEST(BubbleSizeDistribution, SameSeedGivesTheSameRadii) {
  // Claim: the sampler is a pure function of the caller's variate, so one seed gives one sequence
  // bit for bit, and another seed a different one. Reference: determinism rule (STYLE.md §6).
  // Tolerance: exact.
  const BubbleSizeSampler sampler{PowerLawBubbleSizes{}};
  EXPECT_EQ(drawRadii(sampler, 7, 1000), drawRadii(sampler, 7, 1000));
  EXPECT_NE(drawRadii(sampler, 7, 1000), drawRadii(sampler, 8, 1000));
}

TEST(BubbleSizeDistribution, RejectsInvalidParameters) {
  // Claim: every invalid parameter is rejected with std::invalid_argument naming it.
  const auto expectRejected = [](const BubbleSizeDistribution& d, const std::string& field) {
    try {
      const BubbleSizeSampler sampler{d};
      ADD_FAILURE() << "accepted an invalid " << field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  PowerLawBubbleSizes p;
  p.minRadius = 0.0;
  expectRejected(p, "minRadius");
  p = {};
  p.minRadius = 6e-3;
  expectRejected(p, "minRadius");
  p = {};
  p.maxRadius = std::numeric_limits<double>::quiet_NaN();
  expectRejected(p, "maxRadius");
  p = {};
  p.hinzeRadius = -1e-3;
  expectRejected(p, "hinzeRadius");
  p = {};
  p.largeExponent = std::numeric_limits<double>::infinity();
  expectRejected(p, "largeExponent");

  GaussianBubbleSizes g;
  g.meanRadius = 1e-3;
  expectRejected(g, "radiusDeviation");
  g.radiusDeviation = -1e-4;
  expectRejected(g, "radiusDeviation");
  g.radiusDeviation = 1e-4;
  g.meanRadius = 0.0;
  expectRejected(g, "meanRadius");
  g.meanRadius = 1.0;  // 10⁴ deviations above the bounds: Φ cannot tell them apart
  expectRejected(g, "no probability mass");

  const BubbleSizeSampler sampler{PowerLawBubbleSizes{}};
  EXPECT_THROW(sampler.radius(-0.1), std::invalid_argument);
  EXPECT_THROW(sampler.radius(1.5), std::invalid_argument);
  EXPECT_THROW(sampler.radius(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

}  // namespace
}  // namespace fluidsound::sim
