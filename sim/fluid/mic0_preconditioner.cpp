// sim/fluid/mic0_preconditioner.cpp — see mic0_preconditioner.h: the book's MIC(0) factor with
// tuning and safety constants (Bridson 2015, ch. 5).
#include "sim/fluid/mic0_preconditioner.h"

#include <cmath>
#include <cstdint>

namespace fluidsound::sim {

void Mic0Preconditioner::build(const SevenPointMatrix& A) {
  const std::size_t n = A.size();
  precon_.assign(n, 0.0);
  for (std::size_t row = 0; row < n; ++row) {
    double pivot = A.diagonal[row];
    for (int a = 0; a < 3; ++a) {
      const std::int32_t m = A.minusNeighbour[a][row];
      if (m < 0) continue;
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      const double coupling = A.plus[a][m] * precon_[m];
      pivot -= coupling * coupling;
      // Modification: the fill-in that IC(0) drops, moved to the diagonal (row sums kept).
      pivot -= kMicTuning * A.plus[a][m] * (A.plus[b][m] + A.plus[c][m]) * precon_[m] * precon_[m];
    }
    if (pivot < kMicSafety * A.diagonal[row]) pivot = A.diagonal[row];
    precon_[row] = 1.0 / std::sqrt(pivot);
  }
}

void Mic0Preconditioner::apply(const SevenPointMatrix& A, std::span<const double> r,
                               std::span<double> z) {
  const std::size_t n = A.size();
  forward_.resize(n);
  // Solve L·q = r (L lower triangular, L(n, n) = 1/precon(n)), increasing unknown number.
  for (std::size_t row = 0; row < n; ++row) {
    double t = r[row];
    for (int a = 0; a < 3; ++a) {
      const std::int32_t m = A.minusNeighbour[a][row];
      if (m >= 0) t -= A.plus[a][m] * precon_[m] * forward_[m];
    }
    forward_[row] = t * precon_[row];
  }
  // Solve Lᵀ·z = q, decreasing unknown number.
  for (std::size_t row = n; row-- > 0;) {
    double t = forward_[row];
    for (int a = 0; a < 3; ++a) {
      const std::int32_t p = A.plusNeighbour[a][row];
      if (p >= 0) t -= A.plus[a][row] * precon_[row] * z[p];
    }
    z[row] = t * precon_[row];
  }
}

PcgPreconditioner Mic0Preconditioner::forSolve(const SevenPointMatrix& A) {
  return {[this, &A](std::span<const double> r, std::span<double> z) { apply(A, r, z); },
          /*workPerApply=*/1.0};
}

}  // namespace fluidsound::sim
