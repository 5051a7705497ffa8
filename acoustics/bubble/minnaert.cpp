// acoustics/bubble/minnaert.cpp — natural frequency of a bubble: Minnaert (1933), the linearised
// Rayleigh–Plesset equation with surface tension and vapour, and Prosperetti's (1977, 1991)
// complex polytropic function Φ(ω) for the thermal effective polytropic index. docs/physics.md §3.
#include "acoustics/bubble/minnaert.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fluidsound::acoustics {
namespace {

/// |z| (z = √(i/χ), arg z = π/4) above which coth z = 1 in double precision:
/// coth z − 1 = 2e^(−2z)/(1 − e^(−2z)) and |e^(−2z)| = e^(−√2|z|) < e^(−42) ≈ 6e-19 < 2^(−53).
constexpr double kCothUnityModulus = 30.0;

/// |z| below which z coth z − 1 comes from its Taylor series: the direct form loses
/// ≈ log10(1/|z|²) digits to cancellation (1 − 1 + z²/3), the series converges like (|z|/π)^(2n).
constexpr double kCothSeriesModulus = 0.1;

/// Taylor coefficients of z coth z − 1 = Σ c_n z^(2n), c_n = 2^(2n) B_(2n)/(2n)!
/// (Abramowitz & Stegun 1964, 4.5.67): 1/3, −1/45, 2/945, −1/4725, 2/93555, −1382/638512875.
/// For |z| < kCothSeriesModulus the omitted terms are below (0.1/π)^14 ≈ 1e-21 relative.
constexpr std::array<double, 6> kZCothZSeries = {
    1.0 / 3.0, -1.0 / 45.0, 2.0 / 945.0, -1.0 / 4725.0, 2.0 / 93555.0, -1382.0 / 638512875.0};

/// Relative change of ω₀ between fixed-point iterates at which the thermal ω₀ has converged.
constexpr double kFixedPointTolerance = 1e-12;

/// Cap on the fixed-point iterations; the map contracts strongly (κ_eff varies slowly with ω),
/// so convergence to kFixedPointTolerance takes 4–10 steps from 1 µm to 50 cm.
constexpr int kMaxFixedPointIterations = 100;

/// z coth z − 1 for Re z > 0, accurate for small and large |z| alike.
std::complex<double> zCothZMinusOne(std::complex<double> z) {
  const double modulus = std::abs(z);
  if (modulus > kCothUnityModulus) return z - 1.0;  // coth z = 1 to double precision
  if (modulus < kCothSeriesModulus) {
    const std::complex<double> z2 = z * z;
    std::complex<double> sum = 0.0;
    for (auto it = kZCothZSeries.rbegin(); it != kZCothZSeries.rend(); ++it) sum = sum * z2 + *it;
    return sum * z2;
  }
  // coth z = (1 + e^(−2z))/(1 − e^(−2z)): e^(−2z) decays for Re z > 0, so nothing overflows.
  const std::complex<double> w = std::exp(-2.0 * z);
  return z * (1.0 + w) / (1.0 - w) - 1.0;
}

/// Laplace pressure 2σ/R [Pa], or 0 without the surface-tension option.
double laplacePressure(double radius, const LiquidProperties& liquid, const OscillatorModel& model) {
  return model.surfaceTension ? 2.0 * liquid.surfaceTension / radius : 0.0;
}

/// ω₀ [rad/s] from ω₀² = [p_g0·3κ − 2σ/R]/(ρR²) (docs/physics.md §3); throws if the restoring
/// stiffness is not positive (e.g. vapour pressure above the ambient pressure).
double angularFrequencyFromStiffness(double gasPressure0, double threeKappa, double laplace,
                                     double radius, const LiquidProperties& liquid) {
  const double stiffness = gasPressure0 * threeKappa - laplace;  // [Pa]
  if (!(stiffness > 0.0)) {
    throw std::domain_error("naturalAngularFrequency: restoring pressure 3κ·p_g0 − 2σ/R = " +
                            std::to_string(stiffness) + " Pa must be > 0 (radius " +
                            std::to_string(radius) + " m)");
  }
  return std::sqrt(stiffness / (liquid.density * radius * radius));
}

}  // namespace

// Minnaert 1933: f₀ = √(3γp₀/ρ)/(2πR). docs/physics.md §3.
double basicMinnaertFrequency(double radius, const LiquidProperties& liquid) {
  const double gamma = liquid.gas.heatCapacityRatio;
  return std::sqrt(3.0 * gamma * liquid.ambientPressure / liquid.density) /
         (2.0 * std::numbers::pi * radius);
}

// Hydrostatic option p₀ + ρgh (docs/physics.md §3, "Hydrostatic option").
double ambientPressureAt(double depth, const LiquidProperties& liquid, const OscillatorModel& model) {
  const double hydrostatic = model.hydrostatic ? liquid.density * liquid.gravity * depth : 0.0;
  return liquid.ambientPressure + hydrostatic;
}

// Linearised Rayleigh–Plesset equilibrium (Leighton 1994 p. 305): p_g0 = p_amb + 2σ/R − p_v.
// docs/physics.md §3.
double gasPressure(double radius, double ambientPressure, const LiquidProperties& liquid,
                   const OscillatorModel& model) {
  const double vapour = model.vapour ? liquid.vapourPressure : 0.0;
  return ambientPressure + laplacePressure(radius, liquid, model) - vapour;
}

// D_g = K_g/(ρ_g c_p,g), ideal gas ρ_g = p M/(R_gas T). docs/physics.md §2.
double gasThermalDiffusivity(double gasPressure, const GasProperties& gas) {
  const double gasDensity = gasPressure * gas.molarMass / (kGasConstant * gas.temperature);
  return gas.thermalConductivity / (gasDensity * gas.specificHeat);
}

// Prosperetti 1977, 1991; Commander & Prosperetti 1989:
// Φ(ω) = 3γ / (1 − 3(γ−1) iχ [√(i/χ) coth√(i/χ) − 1]), χ = D_g/(ωR²). docs/physics.md §3.
std::complex<double> thermalPolytropicFunction(double angularFrequency, double radius,
                                               double gasPressure, const GasProperties& gas) {
  using namespace std::complex_literals;
  const double gamma = gas.heatCapacityRatio;
  const double chi = gasThermalDiffusivity(gasPressure, gas) / (angularFrequency * radius * radius);
  const std::complex<double> z = std::sqrt(1.0i / chi);  // principal root, arg z = π/4
  const std::complex<double> denominator = 1.0 - 3.0 * (gamma - 1.0) * 1.0i * chi * zCothZMinusOne(z);
  return 3.0 * gamma / denominator;
}

// ω₀² = [3κ(p_amb − p_v + 2σ/R) − 2σ/R]/(ρR²) (linearised Rayleigh–Plesset, Leighton 1994 p. 305;
// Minnaert 1933 for κ = γ; Prosperetti 1991 for κ = Re Φ(ω₀)/3). docs/physics.md §3.
double naturalAngularFrequency(double radius, double ambientPressure,
                               const LiquidProperties& liquid, const OscillatorModel& model) {
  const double laplace = laplacePressure(radius, liquid, model);
  const double gasPressure0 = gasPressure(radius, ambientPressure, liquid, model);
  const double adiabatic = angularFrequencyFromStiffness(
      gasPressure0, 3.0 * liquid.gas.heatCapacityRatio, laplace, radius, liquid);
  if (model.polytropic == PolytropicModel::Adiabatic) return adiabatic;

  // D_g is evaluated at the total internal pressure p_amb + 2σ/R, also when vapour is on
  // (docs/physics.md §3, footnote of table T1).
  const double diffusivityPressure = ambientPressure + laplace;
  double omega = adiabatic;
  for (int iteration = 0; iteration < kMaxFixedPointIterations; ++iteration) {
    const double threeKappa =
        thermalPolytropicFunction(omega, radius, diffusivityPressure, liquid.gas).real();
    const double next = angularFrequencyFromStiffness(gasPressure0, threeKappa, laplace, radius, liquid);
    if (std::abs(next - omega) <= kFixedPointTolerance * next) return next;
    omega = next;
  }
  throw std::runtime_error("naturalAngularFrequency: thermal fixed point did not converge for radius " +
                           std::to_string(radius) + " m");
}

double naturalFrequency(double radius, double ambientPressure, const LiquidProperties& liquid,
                        const OscillatorModel& model) {
  return naturalAngularFrequency(radius, ambientPressure, liquid, model) / (2.0 * std::numbers::pi);
}

}  // namespace fluidsound::acoustics
