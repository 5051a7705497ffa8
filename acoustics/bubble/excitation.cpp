// acoustics/bubble/excitation.cpp — initial amplitude of a new bubble: Czerski & Deane (2010) neck-collapse
// jet forcing (Langlois et al. 2016 Eq. 14) or an initial radial displacement. docs/physics.md §7.3.
#include "acoustics/bubble/excitation.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace fluidsound::acoustics {
namespace {

/// f·R [m/s] of Minnaert's rounding f ≈ 3/R (van den Doel 2005); the jet forcing lasts half its
/// period, T_c = R/(6 m/s) (Langlois et al. 2016, docs/physics.md §7.3).
constexpr double kRoundedMinnaertFrequencyRadius = 3.0;

/// ω₀T_c below which ∫₀^T t² e^(−iω₀t) dt is summed as a power series: the closed form subtracts
/// terms ≈ 2/ω₀³ to leave ≈ T³/3, losing ≈ log10(6/(ω₀T)³) digits; the series has no cancellation
/// and needs < 20 terms up to ω₀T = 1. Only bubbles above ≈ 1.2 cm (capped T_c) use it.
constexpr double kJetSeriesLimit = 1.0;

/// Relative size of a series term at which the power series stops (below 2^(−53)).
constexpr double kSeriesTruncation = 1e-17;

/// Cap on the series terms; for ω₀T ≤ kJetSeriesLimit the terms fall below kSeriesTruncation
/// within 20 (1/n! decay).
constexpr int kMaxSeriesTerms = 40;

/// ∫₀^T t² e^(−iat) dt = [e^(−iat)(i t²/a + 2t/a² − 2i/a³)]₀^T (closed form, integration by parts),
/// or T³ Σ_{n≥0} (−iaT)^n/(n!(n+3)) for small aT.
std::complex<double> quadraticChirpIntegral(double a, double duration) {
  using namespace std::complex_literals;
  const double t = duration;
  if (a * t < kJetSeriesLimit) {
    const std::complex<double> u = -1.0i * a * t;
    std::complex<double> power = 1.0;  // u^n/n!
    std::complex<double> sum = 0.0;
    for (int n = 0; n < kMaxSeriesTerms; ++n) {
      const std::complex<double> term = power / static_cast<double>(n + 3);
      sum += term;
      if (std::abs(term) < kSeriesTruncation * std::abs(sum)) break;
      power *= u / static_cast<double>(n + 1);
    }
    return t * t * t * sum;
  }
  const std::complex<double> atEnd =
      std::exp(-1.0i * a * t) * (1.0i * t * t / a + 2.0 * t / (a * a) - 2.0i / (a * a * a));
  const std::complex<double> atStart = -2.0i / (a * a * a);
  return atEnd - atStart;
}

}  // namespace

// Czerski & Deane 2010 neck-collapse forcing as Langlois et al. 2016 Eq. 14 (`CzerskiJetForcing`):
// F(t) = −9γσ η p_in0 √(1 + η²) t²/(4ρR³) on v̈ + ω₀²v = F/m, m = ρ/(4πR); p(1 m) = ρω₀²|V|/(4π).
// docs/physics.md §7.3.
double jetExcitationAmplitude(double radius, double angularFrequency, const LiquidProperties& liquid,
                              const OscillatorModel& model) {
  const double gamma = liquid.gas.heatCapacityRatio;
  const double sigma = liquid.surfaceTension;
  const double eta = model.jetConeParameter;
  const double rho = liquid.density;
  // p_in0 = p₀ + 2σ/R: the jet is driven by surface tension, so the Laplace term is always present.
  const double innerPressure = liquid.ambientPressure + 2.0 * sigma / radius;
  const double forcePerTimeSquared =
      9.0 * gamma * sigma * eta * innerPressure * std::sqrt(1.0 + eta * eta) /
      (4.0 * rho * radius * radius * radius);                     // |F|/t²
  const double mass = rho / (4.0 * std::numbers::pi * radius);  // m [kg/m⁴]
  const double forcingTime =
      std::min(model.jetMaxDuration, radius / (2.0 * kRoundedMinnaertFrequencyRadius));  // T_c [s]
  // |V| = |∫₀^T_c (F/m) e^(−iω₀t) dt|/ω₀ [m³]: volume amplitude left once the forcing stops.
  const double volumeAmplitude =
      forcePerTimeSquared / mass * std::abs(quadraticChirpIntegral(angularFrequency, forcingTime)) /
      angularFrequency;
  return rho * angularFrequency * angularFrequency * volumeAmplitude / (4.0 * std::numbers::pi);
}

// R = R₀(1 + ε): monopole p(1 m) = ρω₀²R₀³ε (docs/physics.md §6, §7.3).
double displacementExcitationAmplitude(double radius, double angularFrequency, double displacement,
                                       const LiquidProperties& liquid) {
  return liquid.density * angularFrequency * angularFrequency * radius * radius * radius * displacement;
}

double excitationAmplitude(double radius, double angularFrequency, const LiquidProperties& liquid,
                           const OscillatorModel& model) {
  switch (model.excitation) {
    case ExcitationModel::InitialDisplacement:
      return displacementExcitationAmplitude(radius, angularFrequency, model.initialDisplacement, liquid);
    case ExcitationModel::NeckCollapseJet:
      break;
  }
  return jetExcitationAmplitude(radius, angularFrequency, liquid, model);
}

}  // namespace fluidsound::acoustics
