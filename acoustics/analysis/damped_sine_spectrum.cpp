// acoustics/analysis/damped_sine_spectrum.cpp — band energy and centroid of a sampled damped sine (see
// damped_sine_spectrum.h).
#include "acoustics/analysis/damped_sine_spectrum.h"

#include <cmath>
#include <numbers>

namespace fluidsound::acoustics {
namespace {

/// Gauss–Legendre nodes of the ψ integral: 64 bring the error to ~10⁻⁵ relative for every bubble
/// the synthesizer renders at 48 kHz (32 leave 3·10⁻⁴ for the narrowest lines, R = 5 mm).
constexpr int kNodes = 64;

}  // namespace

DampedSineSpectrum::DampedSineSpectrum(double sampleRate) : samplePeriod_(1.0 / sampleRate) {
  // Nodes: roots of the Legendre polynomial P_n by Newton's method from Tricomi's estimate
  // cos(π(i − 1/4)/(n + 1/2)); weights 2/((1 − x²)P_n'(x)²) (Abramowitz & Stegun 25.4.29).
  for (int i = 1; i <= kNodes; ++i) {
    double x = std::cos(std::numbers::pi * (i - 0.25) / (kNodes + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double previous = 1.0, value = x;  // P₀, P₁; Bonnet's recurrence up to P_n
      for (int k = 2; k <= kNodes; ++k) {
        const double next = ((2.0 * k - 1.0) * x * value - (k - 1.0) * previous) / k;
        previous = value;
        value = next;
      }
      derivative = kNodes * (x * value - previous) / (x * x - 1.0);
      const double step = value / derivative;
      x -= step;
      if (std::fabs(step) < 1e-15) break;
    }
    nodes_.push_back(x);
    weights_.push_back(2.0 / ((1.0 - x * x) * derivative * derivative));
  }
}

BandSpectrum DampedSineSpectrum::inBand(double angularFrequency, double decayRate,
                                        const FrequencyBand& band) const {
  const double line = angularFrequency * samplePeriod_;  // ω_dΔt [rad/sample]
  const double width = decayRate * samplePeriod_;        // βΔt
  const double r = std::exp(-width);
  const double numerator = r * std::sin(line) * r * std::sin(line);
  const double twoRCos = 2.0 * r * std::cos(line), rSquared = r * r;
  // |X(θ)|² = numerator / |e^{iθ} − 2r cos(ω_dΔt) + r² e^{−iθ}|²  (X times e^{iθ}, same modulus).
  const auto power = [&](double theta) {
    const double re = std::cos(theta) * (1.0 + rSquared) - twoRCos;
    const double im = std::sin(theta) * (1.0 - rSquared);
    return numerator / (re * re + im * im);
  };
  const double thetaLow = 2.0 * std::numbers::pi * band.low * samplePeriod_;
  const double thetaHigh = 2.0 * std::numbers::pi * band.high * samplePeriod_;
  const double psiLow = std::atan((thetaLow - line) / width),
               psiHigh = std::atan((thetaHigh - line) / width);
  const double half = 0.5 * (psiHigh - psiLow), mid = 0.5 * (psiHigh + psiLow);
  double integral = 0.0, moment = 0.0;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const double psi = mid + half * nodes_[i];
    const double secant = 1.0 / std::cos(psi);
    const double theta = line + width * std::tan(psi);
    const double value =
        weights_[i] * half * power(theta) * width * secant * secant;  // dθ = βΔt sec²ψ dψ
    integral += value;
    moment += value * theta;
  }
  BandSpectrum result;
  result.energy = samplePeriod_ / std::numbers::pi * integral;
  result.centroid =
      integral > 0.0 ? moment / integral / (2.0 * std::numbers::pi * samplePeriod_) : 0.0;
  return result;
}

}  // namespace fluidsound::acoustics
