// tests/acoustics/transfer/chebyshev_bands_test.cpp — the geometric transfer's band
// interpolation (chebyshev_bands.h): exact at the bands and for polynomials of lower degree, and
// the band rule's accuracy for the air phase e^{iτx} (Berrut & Trefethen 2004; Trefethen, ATAP).
#include "acoustics/transfer/chebyshev_bands.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

namespace fluidsound::acoustics {
namespace {

std::complex<double> interpolate(const ChebyshevBands& bands, double x,
                                 double lo, double hi, double tau) {
  std::vector<double> w(static_cast<std::size_t>(bands.count()));
  bands.weightsAt(x, w);
  std::complex<double> sum(0.0);
  for (int q = 0; q < bands.count(); ++q) {
    const double t = (2.0 * bands.node(q) - lo - hi) / (hi - lo);
    sum += w[static_cast<std::size_t>(q)] * std::polar(1.0, tau * t);
  }
  return sum;
}

TEST(ChebyshevBands, ExactAtTheBandsAndForPolynomialsOfLowerDegree) {
  const ChebyshevBands bands(1000.0, 9000.0, 9);
  std::vector<double> w(9);
  for (int q = 0; q < 9; ++q) {
    bands.weightsAt(bands.node(q), w);
    for (int r = 0; r < 9; ++r) EXPECT_EQ(w[static_cast<std::size_t>(r)], q == r ? 1.0 : 0.0);
  }
  auto cubic = [](double x) { return 2e-9 * x * x * x - 3e-5 * x * x + x - 7.0; };
  for (double x = 1000.0; x <= 9000.0; x += 333.0) {
    bands.weightsAt(x, w);
    double sum = 0.0;
    for (int q = 0; q < 9; ++q) sum += w[static_cast<std::size_t>(q)] * cubic(bands.node(q));
    EXPECT_NEAR(sum, cubic(x), 1e-9 * std::abs(cubic(x)) + 1e-9) << x;
  }
  const ChebyshevBands one(5.0, 5.0, 1);
  std::vector<double> single(1);
  one.weightsAt(5.0, single);
  EXPECT_EQ(single[0], 1.0);
}

// The band rule of the geometric transfer, ⌈1.5τ⌉ + 12 bands for a phase spread τ: the Chebyshev
// coefficients of e^{iτx} are J_n(τ), so the interpolation error is below 1e-7 (Trefethen,
// ATAP, Thm 8.2, with the Bessel tail). Checked for τ = 0.5 … 40 at 200 points.
TEST(ChebyshevBands, TheBandRuleInterpolatesTheAirPhaseToOnePartInTenMillion) {
  const double lo = 2000.0, hi = 60000.0;
  for (double tau : {0.5, 2.0, 8.0, 20.0, 40.0}) {
    const ChebyshevBands bands(lo, hi, static_cast<int>(std::ceil(1.5 * tau + 12.0)));
    double worst = 0.0;
    for (int i = 0; i <= 200; ++i) {
      const double x = lo + (hi - lo) * i / 200.0;
      const double t = (2.0 * x - lo - hi) / (hi - lo);
      worst = std::max(worst, std::abs(interpolate(bands, x, lo, hi, tau) - std::polar(1.0, tau * t)));
    }
    EXPECT_LT(worst, 1e-7) << "tau " << tau;
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
