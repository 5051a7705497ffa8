// tests/support/transfer_references.cpp — see transfer_references.h. Sources: separation of
// variables in a rectangle and a cylinder (Morse & Ingard, Theoretical Acoustics, §9.2; Neumann
// zeros j'_mn of J_m as in Abramowitz & Stegun 9.5), the Neumann sphere's modes j_l(kr)P_l^m
// (Morse & Ingard §7.2, A&S 10.1), shared transfer.md §3.
#include "support/transfer_references.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace fluidsound::test {
namespace {

constexpr double kPi = std::numbers::pi;

/// The zeros of f in (from, to], found by scanning at `step` and bisecting each sign change.
std::vector<double> zerosOf(const std::function<double(double)>& f, double from, double to,
                            double step) {
  std::vector<double> zeros;
  double x0 = from;
  double f0 = f(x0);
  for (double x1 = from + step; x1 <= to + 0.5 * step; x1 += step) {
    const double f1 = f(x1);
    if ((f0 < 0.0) != (f1 < 0.0)) {
      double lo = x0, hi = x1, flo = f0;
      for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        const double fm = f(mid);
        if ((fm < 0.0) == (flo < 0.0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      zeros.push_back(0.5 * (lo + hi));
    }
    x0 = x1;
    f0 = f1;
  }
  return zeros;
}

double besselDerivative(int order, double x) {
  if (order == 0) return -std::cyl_bessel_j(1.0, x);
  return 0.5 * (std::cyl_bessel_j(order - 1.0, x) - std::cyl_bessel_j(order + 1.0, x));
}

/// The positive zeros of J_m' up to maxRoot (the scan step 0.05 is well under the zeros'
/// spacing, ≈ π).
std::vector<double> besselDerivativeZeros(int order, double maxRoot) {
  return zerosOf([order](double x) { return besselDerivative(order, x); }, 1e-6, maxRoot, 0.05);
}

/// Gauss–Legendre nodes and weights on [0, length] (Newton on the Legendre recurrence).
void gaussLegendre(int n, double length, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(n, 0.0);
  weights.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / derivative;
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    nodes[i] = 0.5 * length * (1.0 - x);
    weights[i] = length / ((1.0 - x * x) * derivative * derivative);
  }
}

}  // namespace

Complex lossyWavenumberSquared(double angularFrequency, double soundSpeed, double lossFactor) {
  const double k = angularFrequency / soundSpeed;
  return k * k * Complex(1.0, -lossFactor);
}

Complex depthFunction(Complex gammaSquared, double heightAboveFloor, double depth) {
  // cos(γs)/cos(γH) = (e^{q(s−H)} + e^{−q(s+H)}) / (1 + e^{−2qH}), q = iγ with Re q ≥ 0: every
  // exponential is bounded by 1 in modulus (s ≤ H), so evanescent modes do not overflow.
  Complex q = Complex(0.0, 1.0) * std::sqrt(gammaSquared);
  if (q.real() < 0.0) q = -q;
  const double s = heightAboveFloor;
  const double h = depth;
  return (std::exp(q * (s - h)) + std::exp(-q * (s + h))) / (1.0 + std::exp(-2.0 * q * h));
}

Complex narrowTubePressure(Complex surfacePressure, Complex waterWavenumberSquared,
                           double depthBelow, double depth) {
  return surfacePressure * depthFunction(waterWavenumberSquared, depth - depthBelow, depth);
}

BoxSeries::BoxSeries(const RectangularWater& water, const SurfacePressure& surfacePressure,
                     Complex waterWavenumberSquared, const SeriesResolution& resolution)
    : water_(water), wavenumberSquared_(waterWavenumberSquared), modes_(resolution.modes) {
  const int n = resolution.quadraturePoints;
  const int m = modes_;
  const double lx = water.xMax - water.xMin;
  const double lz = water.zMax - water.zMin;
  // p_L at the midpoints, then its cosine coefficients one axis at a time:
  // P_mn = ε_m ε_n / N² Σ_ij p_ij cos(mπ(i + ½)/N) cos(nπ(j + ½)/N), ε_0 = 1, ε_{m>0} = 2.
  std::vector<Complex> samples(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      samples[i + n * j] =
          surfacePressure(water.xMin + (i + 0.5) * lx / n, water.zMin + (j + 0.5) * lz / n);
    }
  }
  std::vector<double> cosines(static_cast<std::size_t>(m) * n);
  for (int p = 0; p < m; ++p) {
    for (int i = 0; i < n; ++i) {
      cosines[i + n * p] = (p == 0 ? 1.0 : 2.0) * std::cos(kPi * p * (i + 0.5) / n) / n;
    }
  }
  std::vector<Complex> alongX(static_cast<std::size_t>(m) * n);  // at p + m·j
  for (int j = 0; j < n; ++j) {
    for (int p = 0; p < m; ++p) {
      Complex sum = 0.0;
      for (int i = 0; i < n; ++i) sum += samples[i + n * j] * cosines[i + n * p];
      alongX[p + m * j] = sum;
    }
  }
  coefficients_.assign(static_cast<std::size_t>(m) * m, 0.0);
  for (int q = 0; q < m; ++q) {
    for (int p = 0; p < m; ++p) {
      Complex sum = 0.0;
      for (int j = 0; j < n; ++j) sum += alongX[p + m * j] * cosines[j + n * q];
      coefficients_[p + m * q] = sum;
    }
  }
}

Complex BoxSeries::pressureAt(const Vec3& point) const {
  const double lx = water_.xMax - water_.xMin;
  const double lz = water_.zMax - water_.zMin;
  const double depth = water_.surfaceHeight - water_.floorHeight;
  const double height = point[1] - water_.floorHeight;
  Complex u = 0.0;
  for (int q = 0; q < modes_; ++q) {
    const double betaZ = kPi * q / lz;
    const double cz = std::cos(betaZ * (point[2] - water_.zMin));
    for (int p = 0; p < modes_; ++p) {
      const double betaX = kPi * p / lx;
      const double cx = std::cos(betaX * (point[0] - water_.xMin));
      const Complex gamma2 = wavenumberSquared_ - betaX * betaX - betaZ * betaZ;
      u += coefficients_[p + modes_ * q] * cx * cz * depthFunction(gamma2, height, depth);
    }
  }
  return u;
}

double besselDerivativeZero(int order, int index) {
  if (order < 0 || index < 1)
    throw std::invalid_argument("besselDerivativeZero: order ≥ 0, index ≥ 1");
  const double upper = order + 4.0 * index + 10.0;  // j'_mn < m + πn + 2 for every m, n
  const std::vector<double> zeros = besselDerivativeZeros(order, upper);
  return zeros.at(static_cast<std::size_t>(index) - 1);
}

CylinderSeries::CylinderSeries(const CylindricalWater& water,
                               const SurfacePressure& surfacePressure,
                               Complex waterWavenumberSquared, const BesselResolution& resolution)
    : water_(water), wavenumberSquared_(waterWavenumberSquared) {
  const double a = water.radius;
  std::vector<double> radii, weights;
  gaussLegendre(resolution.radialPoints, a, radii, weights);
  const int nr = resolution.radialPoints;
  const int nphi = resolution.azimuthPoints;
  const int orders = resolution.maxOrder;
  // Azimuthal Fourier coefficients of p_L on each radius (trapezoid: exact for a periodic
  // trigonometric polynomial of degree < nphi/2; p_L is smooth and periodic).
  std::vector<Complex> azimuthal(static_cast<std::size_t>(nr) * (2 * orders + 1), 0.0);
  for (int i = 0; i < nr; ++i) {
    for (int j = 0; j < nphi; ++j) {
      const double phi = 2.0 * kPi * j / nphi;
      const Complex p = surfacePressure(water.centreX + radii[i] * std::cos(phi),
                                        water.centreZ + radii[i] * std::sin(phi));
      for (int m = -orders; m <= orders; ++m) {
        azimuthal[i + nr * (m + orders)] += p * std::polar(1.0 / nphi, -m * phi);
      }
    }
  }
  for (int m = -orders; m <= orders; ++m) {
    const int am = std::abs(m);
    std::vector<double> zeros = besselDerivativeZeros(am, resolution.maxRoot);
    if (am == 0) zeros.insert(zeros.begin(), 0.0);  // the constant mode
    for (const double zero : zeros) {
      const double alpha = zero / a;
      Complex projection = 0.0;
      for (int i = 0; i < nr; ++i) {
        projection += azimuthal[i + nr * (m + orders)] * std::cyl_bessel_j(am, alpha * radii[i]) *
                      radii[i] * weights[i];
      }
      const double jm = std::cyl_bessel_j(am, zero);
      const double norm = zero == 0.0
                              ? 0.5 * a * a
                              : 0.5 * a * a * (1.0 - double(am * am) / (zero * zero)) * jm * jm;
      modes_.push_back({m, alpha, projection / norm});
    }
  }
}

Complex CylinderSeries::pressureAt(const Vec3& point) const {
  const double dx = point[0] - water_.centreX;
  const double dz = point[2] - water_.centreZ;
  const double r = std::hypot(dx, dz);
  const double phi = std::atan2(dz, dx);
  const double depth = water_.surfaceHeight - water_.floorHeight;
  const double height = point[1] - water_.floorHeight;
  Complex u = 0.0;
  for (const Mode& mode : modes_) {
    u += mode.coefficient * std::cyl_bessel_j(std::abs(mode.order), mode.alpha * r) *
         std::polar(1.0, mode.order * phi) *
         depthFunction(wavenumberSquared_ - mode.alpha * mode.alpha, height, depth);
  }
  return u;
}

double sphericalBesselDerivativeZero(int order, int index) {
  if (order < 0 || index < 1) {
    throw std::invalid_argument("sphericalBesselDerivativeZero: order ≥ 0, index ≥ 1");
  }
  const unsigned l = static_cast<unsigned>(order);
  const auto derivative = [l](double x) {
    if (l == 0) return -std::sph_bessel(1, x);
    return std::sph_bessel(l - 1, x) - (l + 1.0) / x * std::sph_bessel(l, x);
  };
  const double upper = order + 4.0 * index + 10.0;
  return zerosOf(derivative, 1e-6, upper, 0.05).at(static_cast<std::size_t>(index) - 1);
}

double hemisphericalBowlFirstResonance() { return sphericalBesselDerivativeZero(1, 1); }

}  // namespace fluidsound::test
