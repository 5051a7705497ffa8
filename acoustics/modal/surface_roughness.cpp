// acoustics/modal/surface_roughness.cpp — see surface_roughness.h.
#include "acoustics/modal/surface_roughness.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>

#include <unsupported/Eigen/FFT>

namespace fluidsound::acoustics {

RoughnessProfile::RoughnessProfile(double spacing, std::size_t samples, double exponent, double shortest,
                                   double longest, std::uint64_t seed)
    : spacing_(spacing) {
  if (!(spacing > 0.0) || samples < 16 || (samples & (samples - 1)) != 0 || !(shortest > 0.0) ||
      !(longest > shortest))
    throw std::invalid_argument("RoughnessProfile: spacing > 0, samples a power of two >= 16, 0 < shortest < longest");
  // Half a spectrum of random phases, amplitude k^(−β/2) inside the band; its inverse FFT is real.
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  std::vector<std::complex<double>> spectrum(samples / 2 + 1, 0.0);
  const double length = spacing * static_cast<double>(samples);
  for (std::size_t m = 1; m < samples / 2; ++m) {
    const double wavenumber = static_cast<double>(m) / length;  // [1/m]
    const double angle = phase(random);                          // drawn for every m: bands share phases
    if (1.0 / wavenumber < shortest || 1.0 / wavenumber > longest) continue;
    spectrum[m] = std::polar(std::pow(wavenumber, -0.5 * exponent), angle);
  }
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  fft.inv(heights_, spectrum, static_cast<Eigen::Index>(samples));
  double sum = 0.0, squares = 0.0;
  for (double h : heights_) sum += h;
  const double mean = sum / static_cast<double>(samples);
  for (double& h : heights_) h -= mean, squares += h * h;
  const double rms = std::sqrt(squares / static_cast<double>(samples));
  if (!(rms > 0.0)) throw std::invalid_argument("RoughnessProfile: no wavelength of the band fits the profile");
  for (double& h : heights_) h /= rms;
}

double RoughnessProfile::height(double s) const {
  const double x = s / spacing_;
  const double cell = std::floor(x);
  const auto n = static_cast<long long>(heights_.size());
  const auto i = static_cast<std::size_t>(((static_cast<long long>(cell) % n) + n) % n);
  const double a = heights_[i], b = heights_[(i + 1) % heights_.size()];
  return a + (x - cell) * (b - a);
}

RubbingForce rubbingForce(std::span<const RubbingSample> substeps, const RoughnessProfile& surface,
                          const RubbingSettings& settings) {
  RubbingForce out;
  if (substeps.empty()) return out;
  if (!(settings.sampleRate > 0.0) || !(settings.substep > 0.0) || !(settings.quietSpeed > 0.0))
    throw std::invalid_argument("rubbingForce: sample rate, substep and quiet speed must be > 0");
  const double dt = 1.0 / settings.sampleRate, h = settings.substep;
  out.startTime = substeps.front().time - h;
  const double end = substeps.back().time;
  const auto count = static_cast<std::size_t>(std::ceil((end - out.startTime) * settings.sampleRate - 1e-9));
  out.force.resize(count);
  out.surfaceNodes.resize(count);
  out.rolling.resize(count);
  double travelled = 0.0;
  std::size_t k = 0;  // the substep whose midpoint is the last at or before t (or the first)
  for (std::size_t n = 0; n < count; ++n) {
    const double t = out.startTime + (static_cast<double>(n) + 0.5) * dt;
    while (k + 1 < substeps.size() && substeps[k + 1].time - 0.5 * h <= t) ++k;
    const RubbingSample& a = substeps[k];
    const RubbingSample& b = substeps[std::min(k + 1, substeps.size() - 1)];
    const double midA = a.time - 0.5 * h, midB = b.time - 0.5 * h;
    const double u = midB > midA ? std::clamp((t - midA) / (midB - midA), 0.0, 1.0) : 0.0;
    const double load = a.normalForce + u * (b.normalForce - a.normalForce);
    const double speed = a.speed + u * (b.speed - a.speed);
    travelled += speed * dt;
    const double size = settings.roughness * load * speed / (speed + settings.quietSpeed) * surface.height(travelled);
    out.force[n] = (size * a.normal).cast<float>();
    // The substep the sample lies in (not the midpoint before it) says where and how it rubs.
    const RubbingSample& in = substeps[std::min<std::size_t>(
        substeps.size() - 1, static_cast<std::size_t>(std::max(0.0, std::floor((t - out.startTime) / h))))];
    out.surfaceNodes[n] = in.surfaceNode;
    out.rolling[n] = in.rolling ? 1 : 0;
  }
  return out;
}

}  // namespace fluidsound::acoustics
