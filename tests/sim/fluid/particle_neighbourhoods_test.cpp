// Tests of sim/fluid/particle_neighbourhoods.h: the separable passes against the definition, cube by
// cube, on an irregular occupancy.
#include "sim/fluid/particle_neighbourhoods.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

namespace fluidsound::sim {
namespace {

// Claim: for radius 1 and 2, every cell's bits equal the definition evaluated directly over its
// cube — full: the cube inside the grid and every cell holding ≥ count; any: some cell of the
// cube inside the grid holding a particle. Reference: the brute-force definition, exact (bits).
TEST(ParticleNeighbourhoods, EqualTheDefinitionCubeByCube) {
  const Index3 n{12, 7, 8};
  const std::size_t count = 4;
  // A block of cells holding 5 with one short cell (2) at its corner, a few single particles
  // beside it, and nothing at x ≥ 9.
  Array3<std::uint8_t> held(n, 0);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const bool block = i >= 1 && i <= 7 && j >= 1 && j <= 6 && k >= 1 && k <= 7;
        const bool corner = i == 7 && j == 6 && k == 7;
        const bool single = !block && i < 9 && (i + 2 * j + 5 * k) % 6 == 0;
        held(i, j, k) = static_cast<std::uint8_t>(block ? (corner ? 2 : 5) : (single ? 1 : 0));
      }
  CellIndex index;
  index.start.push_back(0);
  for (const std::uint8_t h : held.values()) index.start.push_back(index.start.back() + h);
  for (const int radius : {1, 2}) {
    const Array3<std::uint8_t> flags = particleNeighbourhoods(index, n, count, radius);
    int full = 0, empty = 0;
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          const int at[3] = {i, j, k};
          bool allFull = true, anyHeld = false;
          for (int a = 0; a < 3; ++a)
            allFull = allFull && at[a] - radius >= 0 && at[a] + radius < n[a];
          for (int dk = -radius; dk <= radius; ++dk)
            for (int dj = -radius; dj <= radius; ++dj)
              for (int di = -radius; di <= radius; ++di) {
                const int x = i + di, y = j + dj, z = k + dk;
                if (x < 0 || y < 0 || z < 0 || x >= n[0] || y >= n[1] || z >= n[2]) continue;
                allFull = allFull && held(x, y, z) >= count;
                anyHeld = anyHeld || held(x, y, z) > 0;
              }
          const std::uint8_t expected = static_cast<std::uint8_t>(
              (allFull ? kNeighbourhoodFull : 0) | (anyHeld ? kNeighbourhoodAny : 0));
          ASSERT_EQ(flags(i, j, k), expected)
              << "radius " << radius << " at " << i << " " << j << " " << k;
          full += allFull;
          empty += !anyHeld;
        }
    EXPECT_GT(full, 0) << "radius " << radius;  // the pattern exercises both bits
    EXPECT_GT(empty, 0) << "radius " << radius;
  }
}

}  // namespace
}  // namespace fluidsound::sim
