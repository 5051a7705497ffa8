// tests/acoustics/bubble/bubble_oscillator_test.cpp — one bubble's oscillator constants gathered from
// minnaert.h, damping.h and excitation.h, against tables T1, T2a, T2b and T7 (docs/physics.md).
#include "acoustics/bubble/bubble_oscillator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "acoustics/bubble/minnaert.h"
#include "support/printed_tolerance.h"

namespace fluidsound::acoustics {
namespace {

using test::printedTolerance;

/// Default model at one radius: T1 "σ, κ=γ", T2a δ_total and β, T7 "jet: p(1 m)"
/// [shared physics.md §3, §4, §7.3].
struct DefaultRow {
  double radius;       // [m]
  double frequency;    // f₀ [Hz], printed to 0.1 Hz
  double total;        // δ, printed to 1e-6
  double decayRate;    // β [1/s]
  double decayDigit;   // last printed digit of β [1/s]
  double jetPressure;  // [Pa at 1 m]
};

constexpr std::array<DefaultRow, 7> kDefaultRows = {{
    {0.1e-3, 33044.7, 0.083479, 8666.2, 0.1, 0.6643},
    {0.25e-3, 13174.9, 0.061647, 2551.6, 0.1, 0.6575},
    {0.5e-3, 6580.3, 0.049059, 1014.2, 0.1, 0.6552},
    {1e-3, 3288.3, 0.039479, 407.85, 0.01, 0.6541},
    {2e-3, 1643.7, 0.032356, 167.08, 0.01, 0.6535},
    {4e-3, 821.7, 0.027142, 70.07, 0.01, 0.4964},
    {5e-3, 657.4, 0.025789, 53.26, 0.01, 0.2709},
}};

/// Thermal model at one radius: T1 "σ, κ_eff" and T2b "δ_total Φ", "β Φ".
struct ThermalRow {
  double radius;      // [m]
  double frequency;   // [Hz], printed to 0.1 Hz
  double total;       // δ, printed to 1e-5
  double decayRate;   // β [1/s]
  double decayDigit;  // last printed digit of β [1/s]
};

constexpr std::array<ThermalRow, 7> kThermalRows = {{
    {0.1e-3, 31609.4, 0.08435, 8376.3, 0.1},
    {0.25e-3, 12811.0, 0.06191, 2491.8, 0.1},
    {0.5e-3, 6451.8, 0.04913, 995.7, 0.1},
    {1e-3, 3243.0, 0.03946, 402.05, 0.01},
    {2e-3, 1627.7, 0.03231, 165.22, 0.01},
    {4e-3, 816.1, 0.02709, 69.46, 0.01},
    {5e-3, 653.3, 0.02574, 52.83, 0.01},
}};

constexpr double kFrequencyDigit = 0.1;  // [Hz]
constexpr double kDeltaDigit = 1e-6;
constexpr double kPhiDeltaDigit = 1e-5;

/// T7's jet column is a formula identity at 0.1 % (shared physics.md §7.3, §9 row 12).
constexpr double kJetRelativeTolerance = 1e-3;

/// Expects f₀ = ω₀/2π, δ and β of `constants` at a table row's printed values (f₀ printed to
/// 0.1 Hz, δ to `deltaDigit`, β to the row's decayDigit), each within printedTolerance.
template <typename Row>
void expectPrintedFrequencyAndDamping(const OscillatorConstants& constants, const Row& row,
                                      double deltaDigit) {
  EXPECT_NEAR(constants.angularFrequency / (2.0 * std::numbers::pi), row.frequency,
              printedTolerance(row.frequency, kFrequencyDigit));
  EXPECT_NEAR(constants.dampingConstant, row.total, printedTolerance(row.total, deltaDigit));
  EXPECT_NEAR(constants.decayRate, row.decayRate, printedTolerance(row.decayRate, row.decayDigit));
}

TEST(BubbleOscillator, DefaultModelCombinesTablesT1T2aAndT7) {
  const LiquidProperties liquid;
  const OscillatorModel model;
  for (const DefaultRow& row : kDefaultRows) {
    SCOPED_TRACE(testing::Message() << "R = " << row.radius << " m");
    const OscillatorConstants constants =
        bubbleOscillator(row.radius, liquid.ambientPressure, liquid, model);
    // Claim: ω₀ from the adiabatic + σ model, δ and β = ω₀δ/2 from Devin damping, amplitude from
    // the jet forcing (the defaults of oscillator_model.h). References: T1 "σ, κ=γ", T2a δ_total
    // and β, T7 "jet: p(1 m)". Tolerance: printed precision or 2e-5 relative; 0.1 % for the jet.
    expectPrintedFrequencyAndDamping(constants, row, kDeltaDigit);
    EXPECT_NEAR(constants.amplitude, row.jetPressure, kJetRelativeTolerance * row.jetPressure);
  }
}

TEST(BubbleOscillator, ThermalModelMatchesTablesT1AndT2bPhiColumns) {
  const LiquidProperties liquid;
  OscillatorModel model;
  model.polytropic = PolytropicModel::Thermal;
  for (const ThermalRow& row : kThermalRows) {
    SCOPED_TRACE(testing::Message() << "R = " << row.radius << " m");
    const OscillatorConstants constants =
        bubbleOscillator(row.radius, liquid.ambientPressure, liquid, model);
    // Claim: with κ_eff the frequency is T1's "σ, κ_eff" and the damping uses p_g0|Im Φ|/(ρR²ω₀²)
    // at that frequency. References: T1, T2b "δ_total Φ" and "β Φ". Tolerance: printed precision
    // or 2e-5 relative.
    expectPrintedFrequencyAndDamping(constants, row, kPhiDeltaDigit);
  }
}

TEST(BubbleOscillator, DecayRateIsHalfAngularFrequencyTimesDampingConstant) {
  // Claim: β = ω₀δ/2 for the Devin model (shared physics.md §1, §4). Reference: the returned ω₀
  // and δ. Tolerance: 1e-14 relative, one rounding of a product.
  const LiquidProperties liquid;
  const OscillatorModel model;
  for (const double radius : {10e-6, 1e-3, 5e-2}) {
    const OscillatorConstants constants =
        bubbleOscillator(radius, liquid.ambientPressure, liquid, model);
    const double expected = constants.angularFrequency * constants.dampingConstant / 2.0;
    EXPECT_NEAR(constants.decayRate, expected, 1e-14 * expected);
  }
}

TEST(BubbleOscillator, GivenAmplitudeOverridesExcitationModel) {
  // Claim: an amplitude from the bubble file replaces the excitation model's (bubble_oscillator.h)
  // and leaves frequency and damping unchanged. Reference: the given value and the call without
  // it. Tolerance: exact.
  const LiquidProperties liquid;
  const OscillatorModel model;
  constexpr double kRadius = 1e-3;
  constexpr double kGivenAmplitude = 0.25;  // [Pa at 1 m]
  const OscillatorConstants modelled =
      bubbleOscillator(kRadius, liquid.ambientPressure, liquid, model);
  const OscillatorConstants given =
      bubbleOscillator(kRadius, liquid.ambientPressure, liquid, model, kGivenAmplitude);
  EXPECT_EQ(given.amplitude, kGivenAmplitude);
  EXPECT_EQ(given.angularFrequency, modelled.angularFrequency);
  EXPECT_EQ(given.dampingConstant, modelled.dampingConstant);
  EXPECT_EQ(given.decayRate, modelled.decayRate);
}

TEST(BubbleOscillator, HydrostaticPressureRaisesFrequencyBySection3Factor) {
  // Claim: a 1 mm bubble at 1 m depth with the hydrostatic option rings 1.0471× higher
  // (shared physics.md §3). Reference: that factor. Tolerance: half its last printed digit (5e-5).
  const LiquidProperties liquid;
  OscillatorModel model;
  model.hydrostatic = true;
  constexpr double kRadius = 1e-3;
  constexpr double kDepth = 1.0;  // [m]
  const double surface =
      bubbleOscillator(kRadius, ambientPressureAt(0.0, liquid, model), liquid, model)
          .angularFrequency;
  const double deep =
      bubbleOscillator(kRadius, ambientPressureAt(kDepth, liquid, model), liquid, model)
          .angularFrequency;
  EXPECT_NEAR(deep / surface, 1.0471, 0.5e-4);
}

TEST(BubbleOscillator, ExtremeRadiiGiveFinitePositiveConstants) {
  // Claim: every model combination gives finite, positive ω₀, δ, β and amplitude at R = 10 µm
  // and 5 cm (STYLE.md scale range). Tolerance: exact.
  const LiquidProperties liquid;
  for (const double radius : {10e-6, 5e-2}) {
    for (const PolytropicModel polytropic :
         {PolytropicModel::Adiabatic, PolytropicModel::Thermal}) {
      for (const DampingModel damping : {DampingModel::Devin, DampingModel::VanDenDoel}) {
        for (const ExcitationModel excitation :
             {ExcitationModel::NeckCollapseJet, ExcitationModel::InitialDisplacement}) {
          for (const bool vapour : {false, true}) {
            SCOPED_TRACE(
                testing::Message()
                << "R = " << radius << " m, thermal " << (polytropic == PolytropicModel::Thermal)
                << ", van den Doel " << (damping == DampingModel::VanDenDoel) << ", jet "
                << (excitation == ExcitationModel::NeckCollapseJet) << ", vapour " << vapour);
            OscillatorModel model;
            model.polytropic = polytropic;
            model.damping = damping;
            model.excitation = excitation;
            model.vapour = vapour;
            const OscillatorConstants constants =
                bubbleOscillator(radius, liquid.ambientPressure, liquid, model);
            for (const double value : {constants.angularFrequency, constants.dampingConstant,
                                       constants.decayRate, constants.amplitude}) {
              EXPECT_TRUE(std::isfinite(value));
              EXPECT_GT(value, 0.0);
            }
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
