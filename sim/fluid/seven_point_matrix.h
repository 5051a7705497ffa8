// sim/fluid/seven_point_matrix.h — the symmetric 7-point matrix of the pressure projection over the
// liquid cells, the product with it, and the block size of the solver's deterministic reductions.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace fluidsound::sim {

/// Entries per block of a parallel loop over unknowns and of a dot product (32 KiB of doubles):
/// large enough to amortise the task overhead, small enough that a 32³ grid still spreads over a
/// few threads. Partial sums are added in block order, so results do not depend on threads.
inline constexpr std::size_t kUnknownBlock = 4096;

/// A symmetric 7-point matrix on unknowns numbered in grid order (x fastest, then y, then z), so
/// that every −x/−y/−z neighbour has a smaller number than the unknown itself (required by the
/// MIC(0) sweep order). Off-diagonals are stored once, on the lower-numbered unknown.
struct SevenPointMatrix {
  std::vector<double> diagonal;                             ///< A(n, n)
  std::array<std::vector<double>, 3> plus;                  ///< A(n, n + e_a); 0 when no neighbour
  std::array<std::vector<std::int32_t>, 3> plusNeighbour;   ///< number of n + e_a, or −1
  std::array<std::vector<std::int32_t>, 3> minusNeighbour;  ///< number of n − e_a, or −1

  std::size_t size() const { return diagonal.size(); }
  /// Empties the matrix and sizes it for `n` unknowns (all entries 0, no neighbours).
  void reset(std::size_t n);
  /// y = A·x (parallel over blocks of rows; each row is summed in a fixed order).
  void multiply(std::span<const double> x, std::span<double> y) const;
};

}  // namespace fluidsound::sim
