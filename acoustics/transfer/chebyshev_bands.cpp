// acoustics/transfer/chebyshev_bands.cpp — see chebyshev_bands.h.
#include "acoustics/transfer/chebyshev_bands.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fluidsound::acoustics {

ChebyshevBands::ChebyshevBands(double lo, double hi, int count) {
  if (count < 1 || !(lo <= hi)) throw std::invalid_argument("Chebyshev bands: count ≥ 1, lo ≤ hi");
  const double middle = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  for (int q = 0; q < count; ++q) {
    const double angle = (2 * q + 1) * std::numbers::pi / (2.0 * count);
    nodes_.push_back(middle + half * std::cos(angle));
    barycentric_.push_back((q % 2 == 0 ? 1.0 : -1.0) * std::sin(angle));
  }
}

void ChebyshevBands::weightsAt(double x, std::span<double> weights) const {
  if (weights.size() != nodes_.size())
    throw std::invalid_argument("Chebyshev bands: one weight per band");
  double sum = 0.0;
  for (std::size_t q = 0; q < nodes_.size(); ++q) {
    if (x == nodes_[q]) {
      for (double& w : weights) w = 0.0;
      weights[q] = 1.0;
      return;
    }
    weights[q] = barycentric_[q] / (x - nodes_[q]);
    sum += weights[q];
  }
  for (double& w : weights) w /= sum;
}

}  // namespace fluidsound::acoustics
