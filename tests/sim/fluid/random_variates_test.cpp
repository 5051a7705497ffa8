// tests/sim/fluid/random_variates_test.cpp — the bubble model's random variates: uniform doubles in
// [0, 1) and Poisson counts whose mean and variance equal the requested mean, for small means,
// for means drawn by one inversion, and for means split into parts.
#include "sim/fluid/random_variates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "sim/fluid/random_stream.h"

namespace fluidsound::sim {
namespace {

TEST(RandomVariates, UniformIsInTheUnitIntervalWithMeanOneHalf) {
  // Claim: uniform() lies in [0, 1) with mean ½. Reference: U(0, 1), variance 1/12.
  // Tolerance: 4 standard errors, 4/√(12 N).
  RandomStream random(cellStream(5, 1));
  const int n = 200000;
  double sum = 0.0, lo = 1.0, hi = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = random.uniform();
    sum += u, lo = std::min(lo, u), hi = std::max(hi, u);
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LT(hi, 1.0);
  EXPECT_NEAR(sum / n, 0.5, 4.0 / std::sqrt(12.0 * n));
}

TEST(RandomVariates, PoissonMeanAndVarianceEqualTheRequestedMean) {
  // Claim: poissonVariate(μ) has mean μ and variance μ, for μ from 0.02 to 2500 (above 500 the
  // draw is a sum of parts). Reference: the Poisson law. Tolerance, over N = 20000 draws:
  // 4 standard errors, 4√(μ/N) on the mean and 4√((μ + 2μ²)/N) on the sample variance.
  for (const double mu : {0.02, 1.5, 30.0, 499.0, 700.0, 2500.0}) {
    RandomStream random(cellStream(17, static_cast<std::uint64_t>(mu * 100)));
    const int n = 20000;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
      const double k = static_cast<double>(poissonVariate(mu, random));
      sum += k, sum2 += k * k;
    }
    const double mean = sum / n, variance = (sum2 - n * mean * mean) / (n - 1);
    std::cout << "[ measured ] μ " << mu << ": mean " << mean << ", variance " << variance << "\n";
    EXPECT_NEAR(mean, mu, 4.0 * std::sqrt(mu / n)) << "μ = " << mu;
    EXPECT_NEAR(variance, mu, 4.0 * std::sqrt((mu + 2.0 * mu * mu) / n)) << "μ = " << mu;
  }
}

TEST(RandomVariates, PoissonOfZeroIsZeroAndBadMeansAreRefused) {
  RandomStream random(1);
  EXPECT_EQ(poissonVariate(0.0, random), 0u);
  EXPECT_THROW(poissonVariate(-1.0, random), std::invalid_argument);
  EXPECT_THROW(poissonVariate(std::nan(""), random), std::invalid_argument);
  EXPECT_THROW(poissonVariate(std::numeric_limits<double>::infinity(), random), std::invalid_argument);
}

}  // namespace
}  // namespace fluidsound::sim
