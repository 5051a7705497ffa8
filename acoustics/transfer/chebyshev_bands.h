// acoustics/transfer/chebyshev_bands.h — the geometric transfer's bands: Chebyshev points of the
// first kind over a frame's frequency range, and the barycentric interpolation through them
// (Berrut & Trefethen 2004, "Barycentric Lagrange interpolation", SIAM Review 46(3), eq. 5.3 and
// the first-kind weights of §5). A function analytic in an ellipse around the range, as the
// transfer is once its resonances are taken out, is interpolated with an error that falls
// geometrically with the number of bands (Trefethen, ATAP, Thm 8.2).
#pragma once

#include <span>
#include <vector>

namespace fluidsound::acoustics {

class ChebyshevBands {
 public:
  /// @param count  ≥ 1 bands over [lo, hi] (lo ≤ hi); one band sits at the middle
  ChebyshevBands(double lo, double hi, int count);

  int count() const { return static_cast<int>(nodes_.size()); }
  /// Band q's abscissa, q = 0 … count − 1, descending from near hi to near lo.
  double node(int q) const { return nodes_[static_cast<std::size_t>(q)]; }
  /// The weights ℓ_q(x) of the interpolant through the bands, Σ_q ℓ_q(x)·f_q; exactly the unit
  /// vector at a band. `weights` must hold count() values.
  void weightsAt(double x, std::span<double> weights) const;

 private:
  std::vector<double> nodes_, barycentric_;
};

}  // namespace fluidsound::acoustics
