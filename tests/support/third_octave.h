// tests/support/third_octave.h — a signal's energy per third-octave band, for comparing two
// renders of the same sound (mode compression: tests/acoustics/modal/modal_synthesis_test.cpp and
// tests/bench/modal_bench.cpp).
#pragma once

#include <cmath>
#include <complex>
#include <vector>

#include <unsupported/Eigen/FFT>

namespace fluidsound::test {

/// Energy per third-octave band (centres 100 Hz · 2^{k/3}, k = 0 … 21) of a signal [dB, relative].
inline std::vector<double> thirdOctaveLevels(const std::vector<float>& x, double rate) {
  Eigen::FFT<double> fft;
  std::vector<double> input(x.begin(), x.end());
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, input);
  std::vector<double> levels;
  for (int k = 0; k <= 21; ++k) {
    const double centre = 100.0 * std::pow(2.0, k / 3.0), lo = centre * std::pow(2.0, -1.0 / 6.0),
                 hi = centre * std::pow(2.0, 1.0 / 6.0);
    double energy = 1e-30;
    for (std::size_t b = 0; b < spectrum.size() / 2; ++b) {
      const double f = b * rate / spectrum.size();
      if (f >= lo && f < hi) energy += std::norm(spectrum[b]);
    }
    levels.push_back(10.0 * std::log10(energy));
  }
  return levels;
}

}  // namespace fluidsound::test
