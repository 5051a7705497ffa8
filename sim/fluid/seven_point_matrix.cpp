// sim/fluid/seven_point_matrix.cpp — see seven_point_matrix.h.
#include "sim/fluid/seven_point_matrix.h"

#include "sim/fluid/block_parallel.h"

namespace fluidsound::sim {

void SevenPointMatrix::reset(std::size_t n) {
  diagonal.assign(n, 0.0);
  for (int a = 0; a < 3; ++a) {
    plus[a].assign(n, 0.0);
    plusNeighbour[a].assign(n, -1);
    minusNeighbour[a].assign(n, -1);
  }
}

void SevenPointMatrix::multiply(std::span<const double> x, std::span<double> y) const {
  forEachBlock(size(), kUnknownBlock, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      double sum = diagonal[n] * x[n];
      for (int a = 0; a < 3; ++a) {
        const std::int32_t p = plusNeighbour[a][n];
        const std::int32_t m = minusNeighbour[a][n];
        if (p >= 0) sum += plus[a][n] * x[p];
        if (m >= 0) sum += plus[a][m] * x[m];
      }
      y[n] = sum;
    }
  });
}

}  // namespace fluidsound::sim
