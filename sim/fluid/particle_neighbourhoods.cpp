// sim/fluid/particle_neighbourhoods.cpp — see particle_neighbourhoods.h.
#include "sim/fluid/particle_neighbourhoods.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace fluidsound::sim {

Array3<std::uint8_t> particleNeighbourhoods(const CellIndex& index, const Index3& cells,
                                            std::size_t count, int radius) {
  Array3<std::uint8_t> flags(cells, 0), pass(cells, 0);
  std::uint8_t* const f = flags.data();
  const std::size_t n = flags.elementCount();
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t held = index.start[c + 1] - index.start[c];
    f[c] = static_cast<std::uint8_t>((held >= count ? kNeighbourhoodFull : 0) |
                                     (held > 0 ? kNeighbourhoodAny : 0));
  }
  const int ni = cells[0], nj = cells[1], nk = cells[2];
  const std::size_t sj = static_cast<std::size_t>(ni), sk = sj * nj;
  // x: along each row; the cube's full bit needs all 2r + 1 cells inside the row.
  {
    const std::uint8_t* const from = flags.data();
    std::uint8_t* const to = pass.data();
    tbb::parallel_for(0, nk, [&](int k) {
      for (int j = 0; j < nj; ++j) {
        const std::uint8_t* const in = from + k * sk + j * sj;
        std::uint8_t* const out = to + k * sk + j * sj;
        for (int i = 0; i < ni; ++i) {
          const int lo = std::max(i - radius, 0), hi = std::min(i + radius, ni - 1);
          std::uint8_t all = 0xFF, any = 0;
          for (int m = lo; m <= hi; ++m) all &= in[m], any |= in[m];
          const bool inside = i - radius >= 0 && i + radius < ni;
          out[i] = static_cast<std::uint8_t>((inside ? all & kNeighbourhoodFull : 0) |
                                             (any & kNeighbourhoodAny));
        }
      }
    });
    std::swap(flags, pass);
  }
  // y and z: whole rows at once, the 2r + 1 rows of the cube combined cell by cell.
  for (const int a : {1, 2}) {
    const std::uint8_t* const from = flags.data();
    std::uint8_t* const to = pass.data();
    const int count = a == 1 ? nj : nk;
    const std::size_t step = a == 1 ? sj : sk;
    tbb::parallel_for(0, nk, [&](int k) {
      std::vector<std::uint8_t> all(ni), any(ni);
      for (int j = 0; j < nj; ++j) {
        const int at = a == 1 ? j : k;
        const std::size_t row = k * sk + j * sj;
        const int lo = std::max(at - radius, 0), hi = std::min(at + radius, count - 1);
        std::fill(all.begin(), all.end(), std::uint8_t{0xFF});
        std::fill(any.begin(), any.end(), std::uint8_t{0});
        for (int m = lo; m <= hi; ++m) {
          const std::uint8_t* const in =
              from + row +
              (static_cast<std::ptrdiff_t>(m) - at) * static_cast<std::ptrdiff_t>(step);
          for (int i = 0; i < ni; ++i) all[i] &= in[i], any[i] |= in[i];
        }
        const std::uint8_t fullMask =
            at - radius >= 0 && at + radius < count ? kNeighbourhoodFull : 0;
        std::uint8_t* const out = to + row;
        for (int i = 0; i < ni; ++i)
          out[i] = static_cast<std::uint8_t>((all[i] & fullMask) | (any[i] & kNeighbourhoodAny));
      }
    });
    std::swap(flags, pass);
  }
  return flags;
}

}  // namespace fluidsound::sim
