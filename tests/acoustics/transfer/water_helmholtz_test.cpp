// tests/acoustics/transfer/water_helmholtz_test.cpp — issue 19's acceptance points for the water
// side of the geometric transfer (acoustics::WaterHelmholtz + rigidSurfaceAirPressure +
// transferFromReciprocalPressure) against the analytic references of
// tests/support/transfer_references.h on the shapes of tests/support/water_grid_shapes.h
// (docs/transfer.md, "Reference solutions and their tests"). Every test prints its figures.
#include "acoustics/transfer/water_helmholtz.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/transfer/image_source_transfer.h"
#include "acoustics/transfer/rigid_surface_air_field.h"
#include "support/transfer_references.h"
#include "support/water_grid_shapes.h"

namespace fluidsound::acoustics {
namespace {

using test::Complex;
constexpr double kPi = std::numbers::pi;
/// The stage's default loss (GeometricTransferOptions::lossFactor, 2ρ_a c_a/(ρ_w c_w)).
constexpr double kLoss = 5.59e-4;

const LiquidProperties kWater{};
const AirProperties kAir{};

double angular(double hertz) { return 2.0 * kPi * hertz; }

/// u at `points` by the reciprocal route: p_L at the air points from a unit source at the
/// listener, one solve, u read at each point.
std::vector<Complex> reciprocalPressures(const WaterHelmholtz& water, const HelmholtzFactor& factor,
                                         double omega, const Vec3& listener,
                                         const std::vector<Vec3>& points) {
  std::vector<Complex> airPressure;
  for (const AirPoint& p : water.airPoints()) {
    airPressure.push_back(rigidSurfaceAirPressure(p.position, listener, omega, kAir));
  }
  const Eigen::VectorXcd u = factor.solve(water.rightHandSide(airPressure));
  std::vector<Complex> values;
  for (const Vec3& x : points) values.push_back(water.evaluate(water.sampleAt(x), u, airPressure));
  return values;
}

/// The same with its own factorisation at ω.
std::vector<Complex> reciprocalPressures(const WaterHelmholtz& water, double omega,
                                         const Vec3& listener, const std::vector<Vec3>& points) {
  return reciprocalPressures(water, *water.factorise(omega), omega, listener, points);
}

/// p_L of the listener on the plane y = surface, as the references take it.
test::SurfacePressure surfacePressure(double surface, const Vec3& listener, double omega) {
  return [=](double x, double z) {
    return rigidSurfaceAirPressure({x, surface, z}, listener, omega, kAir);
  };
}

double relativeError(Complex value, Complex reference) {
  return std::abs(std::abs(value) - std::abs(reference)) / std::abs(reference);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The flat case's water: 10 × 7.15 × 2 cm, the surface 0.3 cell (5 mm) or 0.6 cell (2.5 mm)
/// above a face; at 2 kHz the box is acoustically small (k_w H = 0.61, first resonance
/// c_w/(4H) = 5.18 kHz) so it solves in well under a second at 2.5 mm.
constexpr double kBoxDepth = 0.0715;
constexpr double kFlatFrequency = 2000.0;

struct FlatErrors {
  double worst = 0.0;
  double worstAgainstClosedForm = 0.0;
};

/// Bubbles 1, 2, 5 cm deep under x = 4.7 cm, listeners 1 m away at 0°, 10°, 20°, 45°, 80° in the
/// x–y plane: the grid's |u| against the box series; E(θ) (airTransfer) reported beside it.
FlatErrors flatSurfaceErrors(double cellSize) {
  const auto start = std::chrono::steady_clock::now();
  const test::WaterBoxShape shape{0.1, kBoxDepth, 0.02, cellSize, 2};
  const WaterHelmholtz water(test::waterBox(shape), kWater.soundSpeed, kLoss);
  const double omega = angular(kFlatFrequency);
  const Complex k2 = test::lossyWavenumberSquared(omega, kWater.soundSpeed, kLoss);
  const test::RectangularWater box{0.0, 0.1, 0.0, 0.02, 0.0, kBoxDepth};
  const auto factor = water.factorise(omega);
  FlatErrors errors;
  for (const double degrees : {0.0, 10.0, 20.0, 45.0, 80.0}) {
    const double theta = degrees * kPi / 180.0;
    const double xb = 0.047, zb = 0.0105;
    const Vec3 listener{xb + std::sin(theta), kBoxDepth + std::cos(theta), zb};
    const test::BoxSeries series(box, surfacePressure(kBoxDepth, listener, omega), k2);
    std::vector<Vec3> bubbles;
    for (const double d : {0.01, 0.02, 0.05}) bubbles.push_back({xb, kBoxDepth - d, zb});
    const std::vector<Complex> u = reciprocalPressures(water, *factor, omega, listener, bubbles);
    for (std::size_t b = 0; b < bubbles.size(); ++b) {
      const double d = kBoxDepth - bubbles[b][1];
      const Complex reference = series.pressureAt(bubbles[b]);
      const double grid = transferFromReciprocalPressure(u[b], omega, kWater);
      const double exact = transferFromReciprocalPressure(reference, omega, kWater);
      const double closed = airTransfer(omega, d, 1.0, theta, kWater, kAir);
      const double error = relativeError(u[b], reference);
      errors.worst = std::max(errors.worst, error);
      errors.worstAgainstClosedForm =
          std::max(errors.worstAgainstClosedForm, std::abs(grid / closed - 1.0));
      std::printf(
          "flat h=%.4f theta=%4.0f d=%.2f: T grid %.6e box series %.6e (err %.3f %%)"
          " E(theta) closed form %.6e (box/closed %.3f)\n",
          cellSize, degrees, d, grid, exact, 100.0 * error, closed, exact / closed);
    }
  }
  std::printf("flat h=%.4f: %zu unknowns, %.2f s\n", cellSize, water.unknowns(),
              secondsSince(start));
  return errors;
}

// Reference: the rectangular box's cosine series (BoxSeries), the exact solution for the water
// simulated (rigid floor 7.15 cm down and rigid walls 10 × 2 cm); the half-space E(θ) does not hold
// for this water (printed as box/closed) — see docs/transfer.md. Tolerance: issue 19's 2 % at
// 5 mm, and the error must fall at 2.5 mm (second order expected from the ghost fluid and the
// trilinear read).
TEST(WaterHelmholtz, FlatSurfaceMatchesTheBoxSeriesAndConvergesWithTheCell) {
  const FlatErrors coarse = flatSurfaceErrors(0.005);
  const FlatErrors fine = flatSurfaceErrors(0.0025);
  std::printf("flat worst error: 5 mm %.3f %%, 2.5 mm %.3f %% (vs E(theta): %.1f %%, %.1f %%)\n",
              100.0 * coarse.worst, 100.0 * fine.worst, 100.0 * coarse.worstAgainstClosedForm,
              100.0 * fine.worstAgainstClosedForm);
  EXPECT_LT(coarse.worst, 0.02);
  EXPECT_LT(fine.worst, coarse.worst);
}

// Reference: the box series on the water x ∈ [x_w, 10 cm] (a Neumann end at the wall: the bubble's
// images in the wall and in every other wall and the floor; the quarter-space four-image solution
// is its limit for an unbounded box). The wall x_w = 2.17 cm is a third of a cell inside its
// cells, so the face fractions (2/3, exact with 6 × 6 samples) carry it. Tolerance: issue 19's 5 %.
TEST(WaterHelmholtz, RigidWallOneCentimetreFromTheBubbleMatchesItsSeries) {
  const double h = 0.005, wallX = 0.0217;
  const test::WaterBoxShape shape{0.1, kBoxDepth, 0.02, h, 2};
  const auto start = std::chrono::steady_clock::now();
  const WaterHelmholtz water(test::waterBoxWithWall(shape, wallX), kWater.soundSpeed, kLoss);
  const test::RectangularWater box{wallX, 0.1, 0.0, 0.02, 0.0, kBoxDepth};
  const Vec3 bubble{wallX + 0.01, kBoxDepth - 0.02, 0.0105};
  const double theta = 45.0 * kPi / 180.0;
  const Vec3 listener{bubble[0] + std::sin(theta), kBoxDepth + std::cos(theta), bubble[2]};
  const double firstResonance = kWater.soundSpeed / (4.0 * kBoxDepth);
  // 1 and 3 kHz below the first resonance (5.18 kHz), 6.5 kHz above it.
  for (const double hertz : {1000.0, 3000.0, 6500.0}) {
    const double omega = angular(hertz);
    const Complex k2 = test::lossyWavenumberSquared(omega, kWater.soundSpeed, kLoss);
    const test::BoxSeries series(box, surfacePressure(kBoxDepth, listener, omega), k2);
    const Complex reference = series.pressureAt(bubble);
    const Complex u = reciprocalPressures(water, omega, listener, {bubble})[0];
    const double error = relativeError(u, reference);
    std::printf("wall f=%.0f Hz (f1 %.0f Hz): T grid %.6e series %.6e err %.3f %%\n", hertz,
                firstResonance, transferFromReciprocalPressure(u, omega, kWater),
                transferFromReciprocalPressure(reference, omega, kWater), 100.0 * error);
    EXPECT_LT(error, 0.05) << hertz;
  }
  std::printf("wall: %zu unknowns, %.2f s\n", water.unknowns(), secondsSince(start));
}

/// The frequency [Hz] of the maximum of f on [lo, hi] (golden-section search, unimodal f).
double peakFrequency(const std::function<double(double)>& f, double lo, double hi, double width) {
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
  double fa = f(a), fb = f(b);
  while (hi - lo > width) {
    if (fa > fb) {
      hi = b, b = a, fb = fa, a = hi - g * (hi - lo), fa = f(a);
    } else {
      lo = a, a = b, fa = fb, b = lo + g * (hi - lo), fb = f(b);
    }
  }
  return 0.5 * (lo + hi);
}

test::VesselShape tank(double cellSize) { return {0.05, 0.10, 0.0, cellSize, 1, 2, 0.3}; }

// Reference: the cylinder's Bessel series (CylinderSeries) with the listener's p_L, overhead and at
// 30°. Tolerance: issue 19's 5 %, away from the resonances (c_w/(4h) = 3.71 kHz; m = 1 at
// 9.44 kHz: (1.8412/a)² + (π/2h)² = k², excited by the 30° listener) — 10 % bands excluded.
TEST(WaterHelmholtz, CylindricalTankFollowsTheBesselSeriesAcrossFrequency) {
  const auto start = std::chrono::steady_clock::now();
  const WaterHelmholtz water(test::cylindricalTank(tank(0.005)), kWater.soundSpeed, kLoss);
  const test::CylindricalWater cylinder{0.0, 0.0, 0.05, -0.10, 0.0};
  const Vec3 bubble{0.02, -0.03, 0.01};
  for (const double hertz : {500.0, 2000.0, 3000.0, 4500.0, 6000.0, 8000.0, 10000.0}) {
    const double omega = angular(hertz);
    const auto factor = water.factorise(omega);
    const Complex k2 = test::lossyWavenumberSquared(omega, kWater.soundSpeed, kLoss);
    for (const double degrees : {0.0, 30.0}) {
      const double theta = degrees * kPi / 180.0;
      const Vec3 listener{std::sin(theta), std::cos(theta), 0.0};
      const test::CylinderSeries series(cylinder, surfacePressure(0.0, listener, omega), k2);
      const Complex reference = series.pressureAt(bubble);
      const Complex u = reciprocalPressures(water, *factor, omega, listener, {bubble})[0];
      const double error = relativeError(u, reference);
      std::printf("cylinder theta=%.0f f=%.0f Hz: T grid %.6e series %.6e err %.3f %%\n", degrees,
                  hertz, transferFromReciprocalPressure(u, omega, kWater),
                  transferFromReciprocalPressure(reference, omega, kWater), 100.0 * error);
      EXPECT_LT(error, 0.05) << degrees << "° " << hertz << " Hz";
    }
  }
  std::printf("cylinder: %zu unknowns, %.2f s\n", water.unknowns(), secondsSince(start));
}

// Reference: the first zero of cos(k_w h) in the series' constant mode, f₁ = c_w/(4h)
// (shared transfer.md §2–3). Tolerance: issue 19's 2 %; the search resolves 1 Hz.
TEST(WaterHelmholtz, CylindricalTankFirstResonanceIsAQuarterWave) {
  const auto start = std::chrono::steady_clock::now();
  const WaterHelmholtz water(test::cylindricalTank(tank(0.005)), kWater.soundSpeed, kLoss);
  const Vec3 bubble{0.0, -0.05, 0.0}, listener{0.0, 1.0, 0.0};
  const double expected = kWater.soundSpeed / (4.0 * 0.10);
  const double found = peakFrequency(
      [&](double f) {
        return std::abs(reciprocalPressures(water, angular(f), listener, {bubble})[0]);
      },
      0.85 * expected, 1.15 * expected, 1.0);
  std::printf("cylinder resonance: %.1f Hz vs c_w/(4h) %.1f Hz, err %.3f %%, %.2f s\n", found,
              expected, 100.0 * (found / expected - 1.0), secondsSince(start));
  EXPECT_NEAR(found / expected, 1.0, 0.02);
}

// Reference: k a = 2.0816, the first zero of j_1' (hemisphericalBowlFirstResonance, derived in
// transfer_references.h). Tolerance: issue 19's 3 %; the search resolves 4 Hz.
TEST(WaterHelmholtz, HemisphericalBowlFirstResonanceIsTheNeumannBallsFirstOddMode) {
  const auto start = std::chrono::steady_clock::now();
  const double a = 0.05, h = 0.005;
  const WaterHelmholtz water(test::hemisphericalBowl({a, a, 0.0, h, 1, 2, 0.3}), kWater.soundSpeed,
                             kLoss);
  const Vec3 bubble{0.0, -0.02, 0.0}, listener{0.0, 1.0, 0.0};
  const double expected =
      test::hemisphericalBowlFirstResonance() * kWater.soundSpeed / (2.0 * kPi * a);
  const double found = peakFrequency(
      [&](double f) {
        return std::abs(reciprocalPressures(water, angular(f), listener, {bubble})[0]);
      },
      0.9 * expected, 1.1 * expected, 4.0);
  std::printf(
      "bowl resonance (h=%.4f): %.1f Hz vs ka=2.0816 %.1f Hz, err %.3f %%, %zu unknowns, %.2f s\n",
      h, found, expected, 100.0 * (found / expected - 1.0), water.unknowns(), secondsSince(start));
  EXPECT_NEAR(found / expected, 1.0, 0.03);
}

// Reference: the discrete problem itself — the adjoint route (one solve from the bubble, its air
// weights dotted with p_L) and the reciprocal route (one solve from p_L, read at the bubble) are
// the same number by K = Kᵀ. The air weights are the surface velocity the bubble drives (per unit
// p_L); radiating them to the listener by the Rayleigh kernel iωρ_a e^{−ik_aR}/(2πR) is the forward
// route. Tolerance: 1e-6 relative (issue 19: solver tolerance; LU gives ~1e-12).
TEST(WaterHelmholtz, ForwardAdjointAndReciprocalRoutesAgree) {
  const test::WaterBoxShape shape{0.1, kBoxDepth, 0.02, 0.005, 2};
  const WaterHelmholtz water(test::waterBoxWithWall(shape, 0.0217), kWater.soundSpeed, kLoss);
  const double omega = angular(3000.0);
  const double ka = omega / kAir.soundSpeed;
  const auto factor = water.factorise(omega);
  for (const Vec3& bubble : {Vec3{0.03, 0.05, 0.008}, Vec3{0.071, 0.0601, 0.013}}) {
    const PointSample sample = water.sampleAt(bubble);
    const std::vector<Complex> weights = water.airWeights(sample, factor->adjoint(sample));
    for (const double degrees : {0.0, 45.0, 80.0}) {
      const double theta = degrees * kPi / 180.0;
      const Vec3 listener{bubble[0] + std::sin(theta), kBoxDepth + std::cos(theta), bubble[2]};
      const Complex reciprocal = reciprocalPressures(water, omega, listener, {bubble})[0];
      Complex forward = 0.0;
      for (std::size_t a = 0; a < weights.size(); ++a) {
        const Vec3& y = water.airPoints()[a].position;
        const double r = std::hypot(y[0] - listener[0], y[1] - listener[1], y[2] - listener[2]);
        forward += weights[a] * Complex(0.0, omega * kAir.density) * std::polar(1.0, -ka * r) /
                   (2.0 * kPi * r);
      }
      const double error = std::abs(forward - reciprocal) / std::abs(reciprocal);
      std::printf("forward vs reciprocal theta=%.0f: %.3e relative\n", degrees, error);
      EXPECT_LT(error, 1e-6);
    }
    // A uniform p_L = 1: Σ weights is u of the narrow-tube field, 1 + O(k_w² H d) at 3 kHz.
    Complex total = 0.0;
    for (const Complex& w : weights) total += w;
    const Complex tube =
        test::narrowTubePressure(1.0, test::lossyWavenumberSquared(omega, kWater.soundSpeed, kLoss),
                                 kBoxDepth - bubble[1], kBoxDepth);
    EXPECT_LT(std::abs(total - tube), 0.02 * std::abs(tube));
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
