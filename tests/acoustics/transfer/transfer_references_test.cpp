// tests/acoustics/transfer/transfer_references_test.cpp — the analytic references of the
// geometric transfer's tests (tests/support/transfer_references.h) checked against tabulated
// zeros and against each other, so that a water-side test failing means the solver, not the
// reference (docs/transfer.md, "Reference solutions and their tests").
#include "support/transfer_references.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace fluidsound::test {
namespace {

constexpr double kPi = std::numbers::pi;

/// Tabulated zeros to 4 decimals: half a unit of the last digit.
constexpr double kPrintedZeroTolerance = 5e-5;

TEST(TransferReferences, BesselDerivativeZerosMatchTheirTable) {
  // Abramowitz & Stegun, table 9.5: j'_{0,1} = 3.8317, j'_{0,2} = 7.0156, j'_{1,1} = 1.8412,
  // j'_{1,2} = 5.3314, j'_{2,1} = 3.0542.
  EXPECT_NEAR(besselDerivativeZero(0, 1), 3.8317, kPrintedZeroTolerance);
  EXPECT_NEAR(besselDerivativeZero(0, 2), 7.0156, kPrintedZeroTolerance);
  EXPECT_NEAR(besselDerivativeZero(1, 1), 1.8412, kPrintedZeroTolerance);
  EXPECT_NEAR(besselDerivativeZero(1, 2), 5.3314, kPrintedZeroTolerance);
  EXPECT_NEAR(besselDerivativeZero(2, 1), 3.0542, kPrintedZeroTolerance);
}

TEST(TransferReferences, BowlFirstResonanceIsTheFirstZeroOfTheFirstSphericalBesselDerivative) {
  // shared transfer.md §3: k a = 2.0816; A&S table 10.6: a'_{1,1} = 2.0816, a'_{2,1} = 3.3421,
  // a'_{0,1} = 4.4934 (so l = 1 is the lowest odd mode, header comment).
  EXPECT_NEAR(hemisphericalBowlFirstResonance(), 2.0816, kPrintedZeroTolerance);
  EXPECT_NEAR(sphericalBesselDerivativeZero(2, 1), 3.3421, kPrintedZeroTolerance);
  EXPECT_NEAR(sphericalBesselDerivativeZero(0, 1), 4.4934, kPrintedZeroTolerance);
}

TEST(TransferReferences, DepthFunctionIsTheRatioOfCosinesAndStaysFiniteWhenEvanescent) {
  const Complex gamma2(400.0, -0.2);
  const Complex exact = std::cos(std::sqrt(gamma2) * 0.03) / std::cos(std::sqrt(gamma2) * 0.08);
  EXPECT_LT(std::abs(depthFunction(gamma2, 0.03, 0.08) - exact), 1e-12 * std::abs(exact));
  // α = 1e5 /m, 1 cm below the surface: e^{−1000}, no overflow.
  const Complex deep = depthFunction(Complex(-1e10, 0.0), 0.07, 0.08);
  EXPECT_TRUE(std::isfinite(deep.real()));
  EXPECT_LT(std::abs(deep), 1e-300 + 1e-12);
}

/// Uniform p_L: every series reduces to the narrow-tube form (its only mode is the constant one);
/// the projection's quadrature must give the other coefficients ≈ 0.
TEST(TransferReferences, SeriesWithUniformSurfacePressureAreTheNarrowTubeForm) {
  const Complex a(0.3, -1.2);
  const Complex k2 = lossyWavenumberSquared(2.0 * kPi * 3000.0, 1482.0, 5.59e-4);
  const auto uniform = [a](double, double) { return a; };
  const BoxSeries box({0.0, 0.1, 0.0, 0.02, 0.0, 0.07}, uniform, k2, {32, 128});
  const CylinderSeries cylinder({0.0, 0.0, 0.05, -0.1, 0.0}, uniform, k2, {4, 30.0, 48, 16});
  for (const double d : {0.0, 0.01, 0.05, 0.069}) {
    const Complex tubeBox = narrowTubePressure(a, k2, d, 0.07);
    EXPECT_LT(std::abs(box.pressureAt({0.031, 0.07 - d, 0.007}) - tubeBox),
              1e-10 * std::abs(tubeBox));
    const Complex tubeCylinder = narrowTubePressure(a, k2, d, 0.1);
    EXPECT_LT(std::abs(cylinder.pressureAt({0.02, -d, -0.01}) - tubeCylinder),
              1e-10 * std::abs(tubeCylinder));
  }
}

/// An oblique p_L: the series meet the Dirichlet data on the surface (away from the walls, where
/// the cosine series converges like 1/M) and are smooth below it.
TEST(TransferReferences, SeriesReproduceTheirSurfacePressure) {
  const Complex k2 = lossyWavenumberSquared(2.0 * kPi * 2000.0, 1482.0, 5.59e-4);
  const double kappaX = 30.0, kappaZ = 12.0;  // [1/m]
  const auto wave = [=](double x, double z) {
    return std::polar(1.0, kappaX * x + kappaZ * z) * (1.0 + 3.0 * x);
  };
  const BoxSeries box({0.0, 0.1, 0.0, 0.02, 0.0, 0.07}, wave, k2);
  const CylinderSeries cylinder({0.0, 0.0, 0.05, -0.1, 0.0}, wave, k2);
  for (const double x : {0.02, 0.05, 0.08}) {
    const double z = 0.011;
    EXPECT_LT(std::abs(box.pressureAt({x, 0.07, z}) - wave(x, z)), 2e-3) << x;
    const double xc = x - 0.05;
    EXPECT_LT(std::abs(cylinder.pressureAt({xc, 0.0, z}) - wave(xc, z)), 2e-3) << xc;
  }
}

}  // namespace
}  // namespace fluidsound::test
