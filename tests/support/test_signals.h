// tests/support/test_signals.h — signals the acoustics tests analyse: seeded Gaussian noise.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace fluidsound::test {

/// `n` samples of unit-variance Gaussian noise from a fixed seed (mt19937, so every platform
/// draws the same record).
inline std::vector<float> gaussianNoise(std::size_t n, std::uint32_t seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<float> x(n);
  for (float& v : x) v = static_cast<float>(normal(generator));
  return x;
}

}  // namespace fluidsound::test
