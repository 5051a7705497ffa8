// acoustics/binaural/hrir_convolution.cpp — see hrir_convolution.h.
#include "acoustics/binaural/hrir_convolution.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>
#include <vector>

namespace fluidsound::acoustics {

void addConvolutionDirect(std::span<const float> signal, std::span<const float> response,
                          std::size_t delay, double gain, std::span<double> out) {
  for (std::size_t i = 0; i < signal.size(); ++i) {
    if (signal[i] == 0.0f) continue;
    for (std::size_t k = 0; k < response.size(); ++k) {
      const std::size_t n = i + k + delay;
      if (n >= out.size()) break;
      out[n] += gain * static_cast<double>(response[k]) * static_cast<double>(signal[i]);
    }
  }
}

void addConvolution(std::span<const float> signal, std::span<const float> response, std::size_t delay,
                    double gain, std::span<double> out) {
  if (response.empty() || delay >= out.size()) return;
  const std::size_t used = std::min(signal.size(), out.size() - delay);  // later input never lands in out
  // Blocks of B input samples, each convolved by an FFT of size N ≥ B + M − 1 (a power of two).
  std::size_t fftSize = 1024;
  while (fftSize < 4 * response.size()) fftSize *= 2;
  const std::size_t block = fftSize - response.size() + 1;
  Eigen::FFT<double> fft;
  std::vector<double> padded(fftSize, 0.0);
  std::copy(response.begin(), response.end(), padded.begin());
  std::vector<std::complex<double>> responseSpectrum, spectrum;
  fft.fwd(responseSpectrum, padded);
  std::vector<double> result;
  for (std::size_t start = 0; start < used; start += block) {
    const std::size_t count = std::min(block, used - start);
    if (std::all_of(signal.begin() + start, signal.begin() + start + count, [](float v) { return v == 0.0f; }))
      continue;  // silence between bubbles costs nothing
    std::fill(padded.begin(), padded.end(), 0.0);
    std::copy(signal.begin() + start, signal.begin() + start + count, padded.begin());
    fft.fwd(spectrum, padded);
    for (std::size_t f = 0; f < spectrum.size(); ++f) spectrum[f] *= responseSpectrum[f];
    fft.inv(result, spectrum);
    const std::size_t first = start + delay;
    const std::size_t length = std::min(count + response.size() - 1, out.size() - first);
    for (std::size_t n = 0; n < length; ++n) out[first + n] += gain * result[n];
  }
}

void addHeardFrom(const HrirTable& table, std::size_t direction, std::span<const float> signal, double gain,
                  std::span<double> left, std::span<double> right) {
  const auto samples = [&table](double delay) {
    return static_cast<std::size_t>(std::lround(std::max(0.0, delay) * table.sampleRate));
  };
  addConvolution(signal, table.left[direction], samples(table.delayLeft[direction]), gain, left);
  addConvolution(signal, table.right[direction], samples(table.delayRight[direction]), gain, right);
}

}  // namespace fluidsound::acoustics
