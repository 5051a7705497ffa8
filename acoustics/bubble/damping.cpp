// acoustics/bubble/damping.cpp — radiative, viscous and thermal (Devin 1959, or Prosperetti's Φ) damping
// constants and van den Doel's (2005) decay rate. docs/physics.md §4.
#include "acoustics/bubble/damping.h"

#include <cmath>
#include <complex>

#include "acoustics/bubble/minnaert.h"

namespace fluidsound::acoustics {
namespace {

/// X below which Devin's δ_th is summed as a power series: its numerator X(sinh X + sin X)
/// − 2(cosh X − cos X) = X⁶/90 + … is a difference of terms ≈ 2X², so the closed form loses
/// ≈ log10(180/X⁴) digits; at X = 1 both forms agree to ~1e-14.
constexpr double kDevinSeriesLimit = 1.0;

/// Relative size of a series term at which the Devin power series is truncated (below 2^(−53)).
constexpr double kSeriesTruncation = 1e-17;

/// Cap on the Devin series terms; for X ≤ kDevinSeriesLimit successive terms shrink by ≤ X⁴/360,
/// so fewer than ten are ever needed.
constexpr int kMaxSeriesTerms = 32;

/// van den Doel (2005) decay d = a/r + b r^(−3/2): a [m/s] and b [m^(3/2)/s] (docs/physics.md §4).
constexpr double kVanDenDoelLinearCoefficient = 0.13;
constexpr double kVanDenDoelPowerCoefficient = 0.0072;

/// Devin's δ_th for small X from the series (all terms positive, no cancellation):
///   X(sinh X + sin X) − 2(cosh X − cos X) = 2 Σ_{m≥1} 4m X^(4m+2)/(4m+2)!
///   cosh X − cos X = 2 Σ_{m≥0} X^(4m+2)/(4m+2)!,  sinh X − sin X = 2 Σ_{m≥0} X^(4m+3)/(4m+3)!
/// Normalised by X⁶, X² and X³: δ_th = 3(γ−1) X² a / (b + 3(γ−1) c).
double devinThermalSeries(double x, double gamma) {
  const double x4 = x * x * x * x;
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
  double power = 1.0;          // X^(4m)
  double previousPower = 0.0;  // X^(4(m−1)); the m = 0 term of a is zero
  double factorial2 = 2.0;     // (4m+2)!
  for (int m = 0; m < kMaxSeriesTerms; ++m) {
    const double factorial3 = factorial2 * (4 * m + 3);  // (4m+3)!
    const double termA = 4.0 * m * previousPower / factorial2;
    const double termB = power / factorial2;
    a += termA;
    b += termB;
    c += power / factorial3;
    if (m >= 1 && termA < kSeriesTruncation * a && termB < kSeriesTruncation * b) break;
    previousPower = power;
    power *= x4;
    factorial2 = factorial3 * (4 * m + 4) * (4 * m + 5) * (4 * m + 6);
  }
  const double threeGammaMinusOne = 3.0 * (gamma - 1.0);
  return threeGammaMinusOne * x * x * a / (b + threeGammaMinusOne * c);
}

/// Devin's δ_th with numerator and denominator divided by e^X/2, so sinh X, cosh X → 1 ∓ e^(−2X)
/// and sin X, cos X → 2e^(−X)·(sin X, cos X): nothing overflows for large X.
double devinThermalExponential(double x, double gamma) {
  const double e1 = std::exp(-x);
  const double e2 = e1 * e1;
  const double sinhScaled = 1.0 - e2;  // 2e^(−X) sinh X
  const double coshScaled = 1.0 + e2;  // 2e^(−X) cosh X
  const double sinScaled = 2.0 * e1 * std::sin(x);
  const double cosScaled = 2.0 * e1 * std::cos(x);
  const double threeGammaMinusOne = 3.0 * (gamma - 1.0);
  const double numerator = x * (sinhScaled + sinScaled) - 2.0 * (coshScaled - cosScaled);
  const double denominator =
      x * x * (coshScaled - cosScaled) + threeGammaMinusOne * x * (sinhScaled - sinScaled);
  return threeGammaMinusOne * numerator / denominator;
}

}  // namespace

// δ_rad = ω₀R/c_w (Harmonic Fluids, Zheng & James 2009; Langlois 2016 code). docs/physics.md §4.
double radiativeDampingConstant(double angularFrequency, double radius, const LiquidProperties& liquid) {
  return angularFrequency * radius / liquid.soundSpeed;
}

// δ_vis = 4μ/(ρωR²) (Langlois 2016 / Xue 2023 code; from the 4μṘ/R term of Rayleigh–Plesset).
// docs/physics.md §4.
double viscousDampingConstant(double angularFrequency, double radius, const LiquidProperties& liquid) {
  return 4.0 * liquid.viscosity / (liquid.density * angularFrequency * radius * radius);
}

// Devin 1959 (Pfriem theory), X = R√(2ω/D_g). docs/physics.md §4.
double thermalDampingConstant(double angularFrequency, double radius, double gasPressure,
                              const GasProperties& gas) {
  const double diffusivity = gasThermalDiffusivity(gasPressure, gas);
  const double x = radius * std::sqrt(2.0 * angularFrequency / diffusivity);
  return x < kDevinSeriesLimit ? devinThermalSeries(x, gas.heatCapacityRatio)
                               : devinThermalExponential(x, gas.heatCapacityRatio);
}

// van den Doel 2005: d = 0.13/r + 0.0072 r^(−3/2) [1/s], r in m. docs/physics.md §4.
double vanDenDoelDecayRate(double radius) {
  return kVanDenDoelLinearCoefficient / radius + kVanDenDoelPowerCoefficient / (radius * std::sqrt(radius));
}

// Devin 1959: δ = δ_rad + δ_vis + δ_th, β = ω₀δ/2; thermal term from Φ (Prosperetti 1991) with the
// Thermal polytropic model; van den Doel 2005: β = d. docs/physics.md §4.
Damping bubbleDamping(double radius, double angularFrequency, double gasPressure,
                      const LiquidProperties& liquid, const OscillatorModel& model) {
  Damping damping;
  if (model.damping == DampingModel::VanDenDoel) {
    damping.decayRate = vanDenDoelDecayRate(radius);
    damping.dampingConstant = 2.0 * damping.decayRate / angularFrequency;
    return damping;
  }
  // D_g is evaluated at the total internal pressure p_amb + 2σ/R: add back the vapour that
  // gasPressure() subtracted (docs/physics.md §3, footnote of table T1).
  const double diffusivityPressure = model.vapour ? gasPressure + liquid.vapourPressure : gasPressure;
  double thermal = 0.0;
  if (model.polytropic == PolytropicModel::Thermal) {
    // β_th = p_g0|Im Φ|/(2ρR²ω) (Prosperetti 1991), i.e. δ_th = p_g0|Im Φ(ω₀)|/(ρR²ω₀²).
    const std::complex<double> phi =
        thermalPolytropicFunction(angularFrequency, radius, diffusivityPressure, liquid.gas);
    thermal = gasPressure * std::abs(phi.imag()) /
              (liquid.density * radius * radius * angularFrequency * angularFrequency);
  } else {
    thermal = thermalDampingConstant(angularFrequency, radius, diffusivityPressure, liquid.gas);
  }
  damping.dampingConstant = radiativeDampingConstant(angularFrequency, radius, liquid) +
                            viscousDampingConstant(angularFrequency, radius, liquid) + thermal;
  damping.decayRate = angularFrequency * damping.dampingConstant / 2.0;
  return damping;
}

}  // namespace fluidsound::acoustics
