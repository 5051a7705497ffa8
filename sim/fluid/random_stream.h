// sim/fluid/random_stream.h — per-cell random streams: each grid cell draws from its own generator,
// seeded from the scene seed and the cell index, so results do not depend on which thread fills
// which cell.
#pragma once

#include <cstdint>

namespace fluidsound::sim {

/// A 64-bit mix of `seed` and `key` (SplitMix64 finaliser, Steele, Lea & Flood 2014): the seed of
/// one cell's generator. Different keys give unrelated streams.
inline std::uint64_t cellStream(std::uint64_t seed, std::uint64_t key) {
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + key + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace fluidsound::sim
