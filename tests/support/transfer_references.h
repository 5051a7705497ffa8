// tests/support/transfer_references.h — analytic references for the geometric transfer's water
// side (shared transfer.md §3; docs/transfer.md, "Reference solutions and their tests"). Each
// solves (∇² + k_w²) u = 0 in a region of water with u = p_L on its free surface (y = y_s, +y up)
// and ∂u/∂n = 0 on its solid walls, for a given p_L, with the same complex k_w² = (ω/c_w)²(1 − iη)
// as acoustics::WaterHelmholtz. The half-space closed form E(θ) is acoustics::airFarFieldFactor.
#pragma once

#include <complex>
#include <functional>
#include <vector>

#include "sim/core/vec3.h"

namespace fluidsound::test {

using Complex = std::complex<double>;

/// p_L on the surface plane as a function of the horizontal position (x, z) [m].
using SurfacePressure = std::function<Complex(double x, double z)>;

/// k_w² = (ω/c_w)²·(1 − iη) [1/m²], WaterHelmholtz's lossy wavenumber.
Complex lossyWavenumberSquared(double angularFrequency, double soundSpeed, double lossFactor);

/// @brief cos(γ s)/cos(γ H) for γ² = `gammaSquared`, evaluated without overflow for evanescent γ:
///        the depth function of a mode s [m] above a rigid floor under a Dirichlet surface H [m]
///        above it (g'' + γ²g = 0, g'(0) = 0, g(H) = 1).
Complex depthFunction(Complex gammaSquared, double heightAboveFloor, double depth);

/// @brief Narrow-tube limit (shared transfer.md §3): uniform p_L = A on the surface of water of
///        depth h over a rigid floor, rigid side walls: u = A cos(k_w(h − d))/cos(k_w h) at depth
///        d below the surface. Exact for any tank cross-section when p_L is uniform.
Complex narrowTubePressure(Complex surfacePressure, Complex waterWavenumberSquared,
                           double depthBelow, double depth);

/// A rectangular box of water: rigid walls x = xMin, xMax, z = zMin, zMax and floor, the free
/// surface y = surfaceHeight.
struct RectangularWater {
  double xMin = 0.0, xMax = 0.0;
  double zMin = 0.0, zMax = 0.0;
  double floorHeight = 0.0, surfaceHeight = 0.0;
};

/// Modes and quadrature of a series.
struct SeriesResolution {
  int modes = 96;              ///< cosine modes per horizontal axis (rectangle), or max order m
  int quadraturePoints = 512;  ///< midpoint-rule points per axis for the projection of p_L
};

/// @brief The rectangular box's exact solution as a cosine-mode series (separation of variables):
///        u = Σ_mn P_mn cos(mπ(x − x₀)/L_x) cos(nπ(z − z₀)/L_z) cos(γ_mn s)/cos(γ_mn H),
///        γ_mn² = k_w² − (mπ/L_x)² − (nπ/L_z)², s the height above the floor, P_mn the
///        cosine coefficients of p_L (midpoint rule: the projection error falls as 1/N², the
///        coefficients as 1/m², the depth factor as e^{−α d}). Projects p_L once; evaluates
///        anywhere in the water.
class BoxSeries {
 public:
  BoxSeries(const RectangularWater& water, const SurfacePressure& surfacePressure,
            Complex waterWavenumberSquared, const SeriesResolution& resolution = {});
  Complex pressureAt(const Vec3& point) const;

 private:
  RectangularWater water_;
  Complex wavenumberSquared_;
  int modes_;
  std::vector<Complex> coefficients_;  ///< P_mn at m + modes·n
};

/// A vertical cylinder of water: axis x = centreX, z = centreZ, radius a, rigid wall and floor,
/// free surface y = surfaceHeight.
struct CylindricalWater {
  double centreX = 0.0, centreZ = 0.0;
  double radius = 0.05;
  double floorHeight = -0.1, surfaceHeight = 0.0;
};

/// Resolution of the Bessel series: orders |m| ≤ maxOrder, radial roots j'_mn ≤ maxRoot, and the
/// projection's Gauss–Legendre points in r and trapezoid points in the azimuth.
struct BesselResolution {
  int maxOrder = 16;
  double maxRoot = 80.0;
  int radialPoints = 96;
  int azimuthPoints = 64;
};

/// @brief The n-th positive zero (n = 1, 2, …) of J_m'(x), by bracketing and bisection; the
///        constant mode (x = 0 for m = 0) is not counted.
double besselDerivativeZero(int order, int index);

/// @brief The cylinder's exact solution (shared transfer.md §3) as the Bessel series
///        u = Σ_mn P_mn J_m(α_mn r) e^{imφ} cos(γ_mn s)/cos(γ_mn h), α_mn = j'_mn/a (Neumann
///        wall; j'_00 = 0 the constant mode), γ_mn² = k_w² − α_mn², P_mn the projection of p_L on
///        J_m(α_mn r)e^{imφ} with the norm (a²/2)(1 − m²/j'²)J_m(j')² (a²/2 for j' = 0) per 2π.
class CylinderSeries {
 public:
  CylinderSeries(const CylindricalWater& water, const SurfacePressure& surfacePressure,
                 Complex waterWavenumberSquared, const BesselResolution& resolution = {});
  Complex pressureAt(const Vec3& point) const;

 private:
  struct Mode {
    int order;
    double alpha;  ///< α_mn [1/m]
    Complex coefficient;
  };
  CylindricalWater water_;
  Complex wavenumberSquared_;
  std::vector<Mode> modes_;
};

/// @brief The n-th positive zero (n = 1, 2, …) of the derivative of the spherical Bessel
///        function j_l, by bracketing and bisection.
double sphericalBesselDerivativeZero(int order, int index);

/// @brief The filled hemispherical bowl's first resonance k a (shared transfer.md §3). The water
///        is the half ball r < a, y < 0 under a Dirichlet surface y = 0 with a Neumann wall r = a.
///        Reflect it oddly across y = 0: the u of the half ball is the part odd in y of a field in
///        the whole ball with a Neumann wall (u = 0 on y = 0 holds by oddness, and the wall stays
///        Neumann). The ball's modes are j_l(kr) P_l^m(cos ϑ) with j_l'(ka) = 0; P_l^m is odd in
///        y = r cos ϑ when l + m is odd. The lowest odd ones: l = 1, m = 0 (u ∝ j_1(kr) cos ϑ),
///        j_1'(ka) = 0 → k a = 2.0816 (l = 0, the even breathing mode, starts at 4.4934; l = 2,
///        m = 1 at 3.3421). So the first resonance is the first zero of j_1'.
double hemisphericalBowlFirstResonance();

}  // namespace fluidsound::test
