// sim/fluid/cell_interpolation.cpp — see cell_interpolation.h.
#include "sim/fluid/cell_interpolation.h"

#include <algorithm>
#include <cmath>

namespace fluidsound::sim {

CellCentreStencil::CellCentreStencil(const Array3f& field, const GridGeometry& grid, const Vec3& p)
    : cellSize_(grid.cellSize) {
  const Vec3 g = grid.gridFromWorld(p);
  int base[3], next[3];
  for (int a = 0; a < 3; ++a) {
    const double top = static_cast<double>(grid.cells[a] - 1);
    const double x = g[a] - 0.5;  // centre-aligned coordinate
    inside_[a] = x > 0.0 && x < top;
    const double c = std::clamp(x, 0.0, top);
    // A NaN passes the clamp and must not be cast to int (undefined; an index far out of the
    // array): cell 0, and the NaN fraction makes the value NaN.
    base[a] = std::isnan(c) ? 0 : std::min(static_cast<int>(c), std::max(grid.cells[a] - 2, 0));
    next[a] = std::min(base[a] + 1, grid.cells[a] - 1);
    frac_[a] = c - base[a];
  }
  for (int c = 0; c < 8; ++c)
    corner_[c] =
        field(c & 1 ? next[0] : base[0], c & 2 ? next[1] : base[1], c & 4 ? next[2] : base[2]);
}

double CellCentreStencil::value() const {
  double zPlane[2];
  for (int dk = 0; dk < 2; ++dk) {
    double yRow[2];
    for (int dj = 0; dj < 2; ++dj) {
      const double x0 = corner_[dk * 4 + dj * 2], x1 = corner_[dk * 4 + dj * 2 + 1];
      yRow[dj] = x0 + frac_[0] * (x1 - x0);
    }
    zPlane[dk] = yRow[0] + frac_[1] * (yRow[1] - yRow[0]);
  }
  return zPlane[0] + frac_[2] * (zPlane[1] - zPlane[0]);
}

Vec3 CellCentreStencil::gradient() const {
  Vec3 out{0.0, 0.0, 0.0};
  for (int c = 0; c < 8; ++c) {
    const int d[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
    double w[3], dw[3];  // weight per axis and its derivative [1/m]
    for (int a = 0; a < 3; ++a) {
      w[a] = d[a] ? frac_[a] : 1.0 - frac_[a];
      dw[a] = inside_[a] ? (d[a] ? 1.0 : -1.0) / cellSize_ : 0.0;
    }
    const double f = corner_[c];
    out[0] += dw[0] * w[1] * w[2] * f;
    out[1] += w[0] * dw[1] * w[2] * f;
    out[2] += w[0] * w[1] * dw[2] * f;
  }
  return out;
}

double interpolateCellCentres(const Array3f& field, const GridGeometry& grid, const Vec3& p) {
  return CellCentreStencil(field, grid, p).value();
}

}  // namespace fluidsound::sim
