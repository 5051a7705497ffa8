// sim/cell_interpolation.cpp — see cell_interpolation.h.
#include "sim/cell_interpolation.h"

#include <algorithm>

namespace fluidsound::sim {

namespace {

/// The 8 centres around p: base index and fractions per axis; `inside` false where p was clamped
/// (the interpolant does not vary along that axis there).
struct CentreStencil {
  int base[3];
  int next[3];
  double frac[3];
  bool inside[3];

  CentreStencil(const GridGeometry& grid, const Vec3& p) {
    const Vec3 g = grid.gridFromWorld(p);
    for (int a = 0; a < 3; ++a) {
      const double top = static_cast<double>(grid.cells[a] - 1);
      const double x = g[a] - 0.5;  // centre-aligned coordinate
      inside[a] = x > 0.0 && x < top;
      const double c = std::clamp(x, 0.0, top);
      base[a] = std::min(static_cast<int>(c), std::max(grid.cells[a] - 2, 0));
      next[a] = std::min(base[a] + 1, grid.cells[a] - 1);
      frac[a] = c - base[a];
    }
  }
  float corner(const Array3f& f, int c) const {
    return f(c & 1 ? next[0] : base[0], c & 2 ? next[1] : base[1], c & 4 ? next[2] : base[2]);
  }
};

}  // namespace

double interpolateCellCentres(const Array3f& field, const GridGeometry& grid, const Vec3& p) {
  const CentreStencil s(grid, p);
  // Two rows of two pairs: x interpolated first, then y, then z (8 loads, 7 lerps).
  double zPlane[2];
  for (int dk = 0; dk < 2; ++dk) {
    const int k = dk ? s.next[2] : s.base[2];
    double yRow[2];
    for (int dj = 0; dj < 2; ++dj) {
      const float* const row = &field(0, dj ? s.next[1] : s.base[1], k);
      const double x0 = row[s.base[0]], x1 = row[s.next[0]];
      yRow[dj] = x0 + s.frac[0] * (x1 - x0);
    }
    zPlane[dk] = yRow[0] + s.frac[1] * (yRow[1] - yRow[0]);
  }
  return zPlane[0] + s.frac[2] * (zPlane[1] - zPlane[0]);
}

FieldSample sampleCellCentres(const Array3f& field, const GridGeometry& grid, const Vec3& p) {
  const CentreStencil s(grid, p);
  FieldSample out;
  const double h = grid.cellSize;
  for (int c = 0; c < 8; ++c) {
    const int d[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
    double w[3], dw[3];  // weight per axis and its derivative [1/m]
    for (int a = 0; a < 3; ++a) {
      w[a] = d[a] ? s.frac[a] : 1.0 - s.frac[a];
      dw[a] = s.inside[a] ? (d[a] ? 1.0 : -1.0) / h : 0.0;
    }
    const double f = s.corner(field, c);
    out.value += w[0] * w[1] * w[2] * f;
    out.gradient[0] += dw[0] * w[1] * w[2] * f;
    out.gradient[1] += w[0] * dw[1] * w[2] * f;
    out.gradient[2] += w[0] * w[1] * dw[2] * f;
  }
  return out;
}

}  // namespace fluidsound::sim
