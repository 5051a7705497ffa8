// tests/acoustics/bubble/minnaert_test.cpp — natural frequency of a bubble against table T1 and the
// formulas of docs/physics.md §2–§3 (shared physics reference §2–§3).
#include "acoustics/bubble/minnaert.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "acoustics/bubble/damping.h"
#include "support/printed_tolerance.h"

namespace fluidsound::acoustics {
namespace {

using test::printedTolerance;

/// One row of table T1 (Hz, except κ_eff) [shared physics.md §3, T1].
struct T1Row {
  double radius;           // [m]
  double basic;            // basic Minnaert, κ = γ
  double surfaceTension;   // σ, κ = γ (default model)
  double thermal;          // σ, κ_eff (Φ)
  double kappaEffective;   // κ_eff [-]
  double vapour;           // σ + p_v, κ = γ
  double vapourThermal;    // σ + p_v, κ_eff
  double isothermalBasic;  // κ = 1, no σ
};

constexpr std::array<T1Row, 7> kTableT1 = {{
    {0.1e-3, 32865.3, 33044.7, 31609.4, 1.2814, 32665.3, 31238.2, 27776.3},
    {0.25e-3, 13146.1, 13174.9, 12811.0, 1.3238, 13022.6, 12660.8, 11110.5},
    {0.5e-3, 6573.1, 6580.3, 6451.8, 1.3459, 6504.0, 6376.3, 5555.3},
    {1e-3, 3286.5, 3288.3, 3243.0, 1.3617, 3250.2, 3205.1, 2777.6},
    {2e-3, 1643.3, 1643.7, 1627.7, 1.3729, 1624.6, 1608.7, 1388.8},
    {4e-3, 821.6, 821.7, 816.1, 1.3808, 812.2, 806.6, 694.4},
    {5e-3, 657.3, 657.4, 653.3, 1.3829, 649.7, 645.7, 555.5},
}};

/// Frequencies in T1 are printed to 0.1 Hz, κ_eff to 1e-4.
constexpr double kFrequencyDigit = 0.1;
constexpr double kKappaDigit = 1e-4;

/// Radii at the ends of the range the project must handle (STYLE.md: 10 µm to 5 cm).
constexpr std::array<double, 2> kExtremeRadii = {10e-6, 5e-2};

OscillatorModel thermalModel() {
  OscillatorModel model;
  model.polytropic = PolytropicModel::Thermal;
  return model;
}

TEST(Minnaert, BasicFrequencyMatchesTableT1) {
  const LiquidProperties liquid;
  for (const T1Row& row : kTableT1) {
    SCOPED_TRACE(testing::Message() << "R = " << row.radius << " m");
    // Claim: f₀ = √(3γp₀/ρ)/(2πR) (Minnaert 1933). Reference: T1 "basic, κ=γ".
    // Tolerance: printed precision (0.05 Hz) or 2e-5 relative.
    EXPECT_NEAR(basicMinnaertFrequency(row.radius, liquid), row.basic,
                printedTolerance(row.basic, kFrequencyDigit));
  }
}

TEST(Minnaert, RuleOfThumbFrequencyTimesRadiusIs3Point2865) {
  // Claim: f·R = 3.2865 m/s with the default constants (shared physics.md §3).
  // Tolerance: 2e-5 relative (the value is printed to 5e-5 m/s, 1.5e-5 relative).
  const LiquidProperties liquid;
  constexpr double kReferenceProduct = 3.2865;  // [m/s]
  for (const double radius : {1e-5, 1e-3, 5e-2}) {
    EXPECT_NEAR(basicMinnaertFrequency(radius, liquid) * radius, kReferenceProduct,
                printedTolerance(kReferenceProduct, 1e-4));
  }
}

TEST(Minnaert, WithoutSurfaceTensionEqualsBasicMinnaert) {
  // Claim: the linearised Rayleigh–Plesset ω₀ without σ and vapour reduces to Minnaert's formula.
  // Reference: basicMinnaertFrequency (closed form). Tolerance: 1e-12 relative, float rounding
  // only.
  const LiquidProperties liquid;
  OscillatorModel model;
  model.surfaceTension = false;
  for (const T1Row& row : kTableT1) {
    const double basic = basicMinnaertFrequency(row.radius, liquid);
    EXPECT_NEAR(naturalFrequency(row.radius, liquid.ambientPressure, liquid, model), basic,
                1e-12 * basic);
  }
}

TEST(Minnaert, DefaultModelMatchesTableT1WithSurfaceTension) {
  // Claim: the default model is adiabatic κ = γ with surface tension, vapour off
  // (oscillator_model.h), ω₀² = [3γ(p₀ + 2σ/R) − 2σ/R]/(ρR²). Reference: T1 "σ, κ=γ (default)".
  // Tolerance: printed precision (0.05 Hz) or 2e-5 relative.
  const LiquidProperties liquid;
  const OscillatorModel model;
  for (const T1Row& row : kTableT1) {
    SCOPED_TRACE(testing::Message() << "R = " << row.radius << " m");
    EXPECT_NEAR(naturalFrequency(row.radius, liquid.ambientPressure, liquid, model),
                row.surfaceTension, printedTolerance(row.surfaceTension, kFrequencyDigit));
  }
}

TEST(Minnaert, ThermalModelMatchesTableT1EffectivePolytropicColumns) {
  const LiquidProperties liquid;
  const OscillatorModel model = thermalModel();
  for (const T1Row& row : kTableT1) {
    SCOPED_TRACE(testing::Message() << "R = " << row.radius << " m");
    const double omega = naturalAngularFrequency(row.radius, liquid.ambientPressure, liquid, model);
    // Claim: ω₀ solves ω₀² = [p_g0 Re Φ(ω₀) − 2σ/R]/(ρR²) (Prosperetti 1991). Reference: T1
    // "σ, κ_eff (Φ)". Tolerance: printed precision (0.05 Hz) or 2e-5 relative.
    EXPECT_NEAR(omega / (2.0 * std::numbers::pi), row.thermal,
                printedTolerance(row.thermal, kFrequencyDigit));
    // Claim: κ_eff = Re Φ(ω₀)/3 with D_g at p₀ + 2σ/R. Reference: T1 "κ_eff".
    // Tolerance: printed precision (5e-5) or 2e-5 relative.
    const double internalPressure =
        liquid.ambientPressure + 2.0 * liquid.surfaceTension / row.radius;
    const double kappa =
        thermalPolytropicFunction(omega, row.radius, internalPressure, liquid.gas).real() / 3.0;
    EXPECT_NEAR(kappa, row.kappaEffective, printedTolerance(row.kappaEffective, kKappaDigit));
  }
}

TEST(Minnaert, VapourMatchesTableT1AdiabaticAndThermal) {
  const LiquidProperties liquid;
  OscillatorModel adiabatic;
  adiabatic.vapour = true;
  OscillatorModel thermal = thermalModel();
  thermal.vapour = true;
  for (const T1Row& row : kTableT1) {
    SCOPED_TRACE(testing::Message() << "R = " << row.radius << " m");
    // Claim: vapour enters the linearisation multiplied by 3κ: ω₀² = [3κ(p₀ − p_v + 2σ/R) −
    // 2σ/R]/(ρR²), and Φ keeps D_g at p₀ + 2σ/R (T1 footnote). Reference: T1 "σ + p_v, κ=γ" and "σ
    // + p_v, κ_eff". Tolerance: printed precision (0.05 Hz) or 2e-5 relative; the non-linearised
    // variant differs by ≥ 0.9 % (shared physics.md §3) and would fail.
    EXPECT_NEAR(naturalFrequency(row.radius, liquid.ambientPressure, liquid, adiabatic), row.vapour,
                printedTolerance(row.vapour, kFrequencyDigit));
    EXPECT_NEAR(naturalFrequency(row.radius, liquid.ambientPressure, liquid, thermal),
                row.vapourThermal, printedTolerance(row.vapourThermal, kFrequencyDigit));
  }
}

TEST(Minnaert, UnitHeatCapacityRatioGivesTableT1IsothermalColumn) {
  // Claim: the isothermal Minnaert frequency is the basic formula with κ = 1, i.e. γ → 1.
  // Reference: T1 "isothermal basic". Tolerance: printed precision (0.05 Hz) or 2e-5 relative.
  LiquidProperties liquid;
  liquid.gas.heatCapacityRatio = 1.0;
  for (const T1Row& row : kTableT1) {
    SCOPED_TRACE(testing::Message() << "R = " << row.radius << " m");
    EXPECT_NEAR(basicMinnaertFrequency(row.radius, liquid), row.isothermalBasic,
                printedTolerance(row.isothermalBasic, kFrequencyDigit));
  }
}

TEST(Minnaert, HydrostaticFactorAtOneMillimetreMatchesSection3) {
  // Claim: with the hydrostatic option p₀ → p₀ + ρgh raises f₀ (default model, R = 1 mm) by the
  // factors of shared physics.md §3. Tolerance: half the last printed digit of each factor
  // (1.00048 → 5e-6; 1.0024 → 5e-5), the table's rounding.
  const LiquidProperties liquid;
  OscillatorModel model;
  model.hydrostatic = true;
  constexpr double kRadius = 1e-3;
  struct Row {
    double depth;      // [m]
    double factor;     // f(p₀ + ρgh)/f(p₀)
    double lastDigit;  // of the printed factor
  };
  constexpr std::array<Row, 5> kFactors = {{{0.01, 1.00048, 1e-5},
                                            {0.05, 1.0024, 1e-4},
                                            {0.10, 1.0048, 1e-4},
                                            {0.30, 1.0144, 1e-4},
                                            {1.0, 1.0471, 1e-4}}};
  const double surface = naturalFrequency(kRadius, liquid.ambientPressure, liquid, model);
  for (const Row& row : kFactors) {
    SCOPED_TRACE(testing::Message() << "h = " << row.depth << " m");
    const double deep =
        naturalFrequency(kRadius, ambientPressureAt(row.depth, liquid, model), liquid, model);
    EXPECT_NEAR(deep / surface, row.factor, 0.5 * row.lastDigit);
  }
  // Claim: without the option the ambient pressure is p₀ at any depth (exact).
  EXPECT_EQ(ambientPressureAt(1.0, liquid, OscillatorModel{}), liquid.ambientPressure);
}

TEST(Minnaert, GasThermalDiffusivityAtOneAtmosphereMatchesSection2) {
  // Claim: D_g = K_g/(ρ_g c_p,g), ρ_g = pM/(R_gas T). Reference: shared physics.md §2, at 1 atm
  // D_g = 2.1378e-5 m²/s. Tolerance: half the last printed digit (5e-10 m²/s, 2.3e-5 relative).
  const GasProperties gas;
  EXPECT_NEAR(gasThermalDiffusivity(101325.0, gas), 2.1378e-5, 0.5e-9);
}

TEST(Minnaert, GasPressureFollowsSurfaceTensionAndVapourOptions) {
  // Claim: p_g0 = p_amb + 2σ/R − p_v, each term switched by its option (Leighton 1994 p. 305).
  // Reference: the closed form. Tolerance: 1e-12 relative, float rounding only.
  const LiquidProperties liquid;
  constexpr double kRadius = 1e-3;
  constexpr double kAmbient = 2e5;
  const double laplace = 2.0 * liquid.surfaceTension / kRadius;
  OscillatorModel model;
  EXPECT_NEAR(gasPressure(kRadius, kAmbient, liquid, model), kAmbient + laplace, 1e-12 * kAmbient);
  model.vapour = true;
  EXPECT_NEAR(gasPressure(kRadius, kAmbient, liquid, model),
              kAmbient + laplace - liquid.vapourPressure, 1e-12 * kAmbient);
  model.surfaceTension = false;
  EXPECT_NEAR(gasPressure(kRadius, kAmbient, liquid, model), kAmbient - liquid.vapourPressure,
              1e-12 * kAmbient);
}

TEST(Minnaert, ThermalPolytropicFunctionTendsToIsothermalAndAdiabaticLimits) {
  // Claim: Φ → 3 (isothermal, κ = 1) when heat diffuses through the bubble in a period (|z| → 0)
  // and Φ → 3γ (adiabatic) when it cannot (|z| → ∞) (Prosperetti 1991). Reference: these limits.
  // Tolerance: the leading corrections, |Φ/3 − 1| ≈ (γ−1)|z|²/(15γ) ≈ 2e-10 at |z| = 1e-4 (1e-8
  // allowed), |Φ/3γ − 1| ≈ 3(γ−1)/|z| ≈ 1.2e-6 at |z| = 1e6 (1e-5 allowed).
  const GasProperties gas;
  constexpr double kRadius = 1e-3;
  constexpr double kPressure = 101325.0;
  const double diffusivity = gasThermalDiffusivity(kPressure, gas);
  // |z|² = ωR²/D_g.
  const auto omegaFor = [&](double zModulus) {
    return zModulus * zModulus * diffusivity / (kRadius * kRadius);
  };
  const std::complex<double> slow =
      thermalPolytropicFunction(omegaFor(1e-4), kRadius, kPressure, gas);
  EXPECT_NEAR(slow.real(), 3.0, 3.0 * 1e-8);
  EXPECT_NEAR(slow.imag(), 0.0, 3.0 * 1e-8);
  const std::complex<double> fast =
      thermalPolytropicFunction(omegaFor(1e6), kRadius, kPressure, gas);
  const double adiabatic = 3.0 * gas.heatCapacityRatio;
  EXPECT_NEAR(fast.real(), adiabatic, adiabatic * 1e-5);
  EXPECT_NEAR(fast.imag(), 0.0, adiabatic * 1e-5);
}

TEST(Minnaert, ThermalPolytropicFunctionIsContinuousAcrossItsEvaluationBranches) {
  // Claim: Φ is smooth; the Taylor series (small |z|), the exponential coth and coth = 1 (large
  // |z|) join without a step. Reference: Φ just across each switch (|z| = 0.1 and 30).
  // Tolerance: 1e-8 relative: a relative step of 2e-9 in |z| moves Φ by < 2e-9·|d ln Φ/d ln|z||
  // < 2e-9, and each branch is accurate to ~1e-14 at the switch.
  const GasProperties gas;
  constexpr double kRadius = 1e-3;
  constexpr double kPressure = 101325.0;
  const double diffusivity = gasThermalDiffusivity(kPressure, gas);
  for (const double zModulus : {0.1, 30.0}) {
    SCOPED_TRACE(testing::Message() << "|z| = " << zModulus);
    const double below =
        (zModulus * (1.0 - 1e-9)) * (zModulus * (1.0 - 1e-9)) * diffusivity / (kRadius * kRadius);
    const double above =
        (zModulus * (1.0 + 1e-9)) * (zModulus * (1.0 + 1e-9)) * diffusivity / (kRadius * kRadius);
    const std::complex<double> phiBelow = thermalPolytropicFunction(below, kRadius, kPressure, gas);
    const std::complex<double> phiAbove = thermalPolytropicFunction(above, kRadius, kPressure, gas);
    EXPECT_LT(std::abs(phiAbove - phiBelow), 1e-8 * std::abs(phiBelow))
        << phiBelow << " vs " << phiAbove;
  }
}

TEST(Minnaert, RealPartOfPhiEqualsDevinClosedFormPolytropicIndex) {
  // Claim: Devin's (1959) κ = γ / ((1 + δ_th²)(1 + (3(γ−1)/X)(sinh X − sin X)/(cosh X − cos X))),
  // X = R√(2ω/D_g), equals Re Φ/3 (shared physics.md §3: "to machine precision" — two independently
  // recalled formulas). Reference: Devin's form, evaluated here with δ_th from damping.h.
  // Tolerance: 1e-12 relative (float rounding; X ≤ 100 here, so sinh/cosh do not overflow).
  const LiquidProperties liquid;
  const OscillatorModel model;
  const double gamma = liquid.gas.heatCapacityRatio;
  for (const T1Row& row : kTableT1) {
    SCOPED_TRACE(testing::Message() << "R = " << row.radius << " m");
    const double omega = naturalAngularFrequency(row.radius, liquid.ambientPressure, liquid, model);
    const double pressure = gasPressure(row.radius, liquid.ambientPressure, liquid, model);
    const double x =
        row.radius * std::sqrt(2.0 * omega / gasThermalDiffusivity(pressure, liquid.gas));
    const double deltaThermal = thermalDampingConstant(omega, row.radius, pressure, liquid.gas);
    const double devinKappa =
        gamma / ((1.0 + deltaThermal * deltaThermal) *
                 (1.0 + 3.0 * (gamma - 1.0) / x * (std::sinh(x) - std::sin(x)) /
                            (std::cosh(x) - std::cos(x))));
    const double phiKappa =
        thermalPolytropicFunction(omega, row.radius, pressure, liquid.gas).real() / 3.0;
    EXPECT_NEAR(phiKappa, devinKappa, 1e-12 * devinKappa);
  }
}

TEST(Minnaert, ThermalFixedPointSatisfiesItsFrequencyEquation) {
  // Claim: the iteration converges, ρR²ω₀² = p_g0 Re Φ(ω₀) − 2σ/R, from 10 µm to 5 cm, with and
  // without vapour. Reference: the equation itself (shared physics.md §3).
  // Tolerance: 1e-10 relative: the iteration stops at a 1e-12 relative step and the map contracts
  // (|dω_next/dω| < 1), so the residual is a small multiple of 1e-12.
  const LiquidProperties liquid;
  for (const bool vapour : {false, true}) {
    OscillatorModel model = thermalModel();
    model.vapour = vapour;
    for (const double radius : {10e-6, 0.1e-3, 1e-3, 5e-3, 5e-2}) {
      SCOPED_TRACE(testing::Message() << "R = " << radius << " m, vapour " << vapour);
      const double omega = naturalAngularFrequency(radius, liquid.ambientPressure, liquid, model);
      const double laplace = 2.0 * liquid.surfaceTension / radius;
      const double phi =
          thermalPolytropicFunction(omega, radius, liquid.ambientPressure + laplace, liquid.gas)
              .real();
      const double lhs = liquid.density * radius * radius * omega * omega;
      const double rhs = gasPressure(radius, liquid.ambientPressure, liquid, model) * phi - laplace;
      EXPECT_NEAR(lhs, rhs, 1e-10 * rhs);
    }
  }
}

TEST(Minnaert, NyquistRadiiMatchSection3) {
  // Claim: the smallest radius whose default-model frequency is below Nyquist is 0.1496 mm at
  // 44.1 kHz, 0.1375 mm at 48 kHz, 0.0690 mm at 96 kHz (shared physics.md §3).
  // Tolerance: the printed radius ± half its last digit (0.05 µm) must bracket the crossing.
  const LiquidProperties liquid;
  const OscillatorModel model;
  struct Row {
    double sampleRate;  // [Hz]
    double radius;      // [m]
  };
  constexpr double kHalfDigit = 0.05e-6;  // [m]
  for (const Row& row :
       {Row{44100.0, 0.1496e-3}, Row{48000.0, 0.1375e-3}, Row{96000.0, 0.0690e-3}}) {
    SCOPED_TRACE(testing::Message() << "fs = " << row.sampleRate << " Hz");
    const double nyquist = row.sampleRate / 2.0;
    EXPECT_GT(naturalFrequency(row.radius - kHalfDigit, liquid.ambientPressure, liquid, model),
              nyquist);
    EXPECT_LT(naturalFrequency(row.radius + kHalfDigit, liquid.ambientPressure, liquid, model),
              nyquist);
  }
}

TEST(Minnaert, ExtremeRadiiGiveFinitePositiveFrequencies) {
  // Claim: every model option gives a finite ω₀ > 0 at R = 10 µm and 5 cm (STYLE.md scale range).
  // Reference: finiteness and sign. Tolerance: exact.
  const LiquidProperties liquid;
  for (const double radius : kExtremeRadii) {
    for (const PolytropicModel polytropic :
         {PolytropicModel::Adiabatic, PolytropicModel::Thermal}) {
      for (const bool vapour : {false, true}) {
        for (const bool hydrostatic : {false, true}) {
          SCOPED_TRACE(testing::Message() << "R = " << radius << " m, thermal "
                                          << (polytropic == PolytropicModel::Thermal) << ", vapour "
                                          << vapour << ", hydrostatic " << hydrostatic);
          OscillatorModel model;
          model.polytropic = polytropic;
          model.vapour = vapour;
          model.hydrostatic = hydrostatic;
          const double ambient = ambientPressureAt(1.0, liquid, model);
          const double omega = naturalAngularFrequency(radius, ambient, liquid, model);
          EXPECT_TRUE(std::isfinite(omega));
          EXPECT_GT(omega, 0.0);
        }
      }
    }
  }
}

TEST(Minnaert, NonPositiveRestoringPressureThrows) {
  // Claim: a bubble with no restoring force (vapour pressure far above the ambient pressure) is
  // reported, not turned into NaN. Reference: 3κ(p_amb − p_v + 2σ/R) − 2σ/R < 0. Tolerance: exact.
  LiquidProperties liquid;
  liquid.ambientPressure = 100.0;  // [Pa], far below p_v = 2339 Pa
  OscillatorModel model;
  model.vapour = true;
  EXPECT_THROW(naturalAngularFrequency(5e-2, liquid.ambientPressure, liquid, model),
               std::domain_error);
}

}  // namespace
}  // namespace fluidsound::acoustics
