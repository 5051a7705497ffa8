// sim/fluid/random_variates.h — small, fully specified random number streams and the variates the
// bubble model draws from them (uniform, Poisson), so results are bit-identical on any standard
// library (std::poisson_distribution's algorithm is implementation-defined) and any thread count.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

namespace fluidsound::sim {

/// A SplitMix64 sequence (Steele, Lea & Flood 2014): state += golden gamma, output = the mixed
/// state. Seed it with cellStream(seed, key) (random_stream.h) for one stream per key.
class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1): the top 53 bits, exactly representable.
  double uniform() { return std::ldexp(static_cast<double>(next() >> 11), -53); }

 private:
  std::uint64_t state_;
};

/// Largest mean drawn by one inversion: e^(−500) ≈ 7e−218 is still a normal double, and larger
/// means are drawn as sums of independent parts (a sum of Poisson variates is Poisson).
inline constexpr double kPoissonInversionMean = 500.0;

/// @brief A Poisson variate of the given mean [count], by inversion of the cumulative distribution
///        (one uniform per part of mean ≤ kPoissonInversionMean; cost O(mean)).
/// @throws std::invalid_argument for a negative or non-finite mean
inline std::uint64_t poissonVariate(double mean, RandomStream& random) {
  if (!(std::isfinite(mean) && mean >= 0.0)) {
    std::ostringstream message;
    message << "poissonVariate: mean must be a finite number ≥ 0, got " << mean;
    throw std::invalid_argument(message.str());
  }
  std::uint64_t total = 0;
  double remaining = mean;
  while (remaining > 0.0) {
    const double part = std::min(remaining, kPoissonInversionMean);
    remaining -= part;
    const double u = random.uniform();
    double p = std::exp(-part), cumulative = p;
    std::uint64_t k = 0;
    // Stops when the next term no longer changes the sum: rounding may leave the sum a few ulps
    // short of 1, and u above it would otherwise run on into the far tail.
    while (u >= cumulative) {
      ++k;
      p *= part / static_cast<double>(k);
      if (cumulative + p == cumulative) break;
      cumulative += p;
    }
    total += k;
  }
  return total;
}

}  // namespace fluidsound::sim
