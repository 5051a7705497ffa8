// tests/sim/fluid/cell_interpolation_test.cpp — the trilinear interpolant through the cell centres and
// its gradient, read from one stencil of 8 centres (the entrainment's φ and normal).
#include "sim/fluid/cell_interpolation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fluidsound::sim {
namespace {

GridGeometry smallGrid() {
  GridGeometry g;
  g.cells = {6, 5, 7};
  g.cellSize = 0.01;
  g.origin = {0.1, -0.2, 0.3};
  return g;
}

/// f = a·x + b at every cell centre [m].
Array3f linearField(const GridGeometry& g, const Vec3& a, double b) {
  Array3f f(g.cells);
  for (int k = 0; k < g.cells[2]; ++k)
    for (int j = 0; j < g.cells[1]; ++j)
      for (int i = 0; i < g.cells[0]; ++i) {
        const Vec3 x = g.cellCentre(i, j, k);
        f(i, j, k) = static_cast<float>(a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + b);
      }
  return f;
}

TEST(CellInterpolation, ALinearFieldIsReproducedWithItsGradient) {
  // Claim: inside the hull of the centres the trilinear interpolant of a linear field is the field
  // itself and its gradient the field's slope; interpolateCellCentres gives the stencil's value.
  // Reference: a·x + b and a. Tolerance: the float storage of the centre values (|f| ≤ 0.2:
  // 1.5e-8 each), i.e. 1e-7 in the value and, over a difference across one cell of 0.01 m, 2e-5
  // in the gradient (of components up to 3).
  const GridGeometry g = smallGrid();
  const Vec3 a{1.5, -2.0, 3.0};
  const double b = -1.0;
  const Array3f f = linearField(g, a, b);
  for (int n = 0; n < 50; ++n) {  // positions spread over the hull (golden-ratio steps)
    const Vec3 x{g.origin[0] + g.cellSize * (0.5 + 5.0 * std::fmod(0.3 + n * 0.6180339887, 1.0)),
                 g.origin[1] + g.cellSize * (0.5 + 4.0 * std::fmod(0.2 + n * 0.7548776662, 1.0)),
                 g.origin[2] + g.cellSize * (0.5 + 6.0 * std::fmod(0.1 + n * 0.5698402910, 1.0))};
    const CellCentreStencil s(f, g, x);
    const double exact = a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + b;
    EXPECT_NEAR(s.value(), exact, 1e-7);
    EXPECT_EQ(s.value(), interpolateCellCentres(f, g, x));
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_NEAR(s.gradient()[axis], a[axis], 2e-5) << "axis " << axis;
  }
}

TEST(CellInterpolation, OutsideTheCentresTheFieldIsConstantAlongTheClampedAxis) {
  // Claim: beyond the outermost centres along an axis the position is clamped: the value is that
  // at the clamped position and the gradient along that axis is zero, the others unchanged.
  // Reference: the value at the projection onto the hull; 0 and a. Tolerance: as above.
  const GridGeometry g = smallGrid();
  const Vec3 a{1.5, -2.0, 3.0};
  const Array3f f = linearField(g, a, 0.25);
  const Vec3 inside{g.origin[0] + 0.031, g.origin[1] + 0.027, g.origin[2] + 0.044};
  Vec3 below = inside;
  below[1] = g.origin[1] - 0.02;  // under the first centre (0.005 above the origin)
  const CellCentreStencil clamped(f, g, below),
      projected(f, g, {inside[0], g.origin[1] + 0.005, inside[2]});
  EXPECT_NEAR(clamped.value(), projected.value(), 1e-12);
  EXPECT_EQ(clamped.gradient()[1], 0.0);
  EXPECT_NEAR(clamped.gradient()[0], a[0], 2e-5);
  EXPECT_NEAR(clamped.gradient()[2], a[2], 2e-5);
}

TEST(CellInterpolation, ANanCoordinateGivesNanNotAReadOutsideTheArray) {
  // Claim: a NaN coordinate (a position that blew up) passes std::clamp; it gives a NaN value and
  // never an index outside the field (casting NaN to int gave INT_MIN, a read far before the
  // array), while ±inf is clamped to the outermost centres like any far position.
  // Reference: NaN propagates; the clamped value of the test above. Tolerance: as above.
  const GridGeometry g = smallGrid();
  const Array3f f = linearField(g, {1.5, -2.0, 3.0}, 0.25);
  const Vec3 inside{g.origin[0] + 0.031, g.origin[1] + 0.027, g.origin[2] + 0.044};
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 p = inside;
    p[axis] = std::nan("");
    EXPECT_TRUE(std::isnan(interpolateCellCentres(f, g, p))) << "axis " << axis;
    p[axis] = HUGE_VAL;
    Vec3 edge = inside;
    edge[axis] = g.origin[axis] + g.cellSize * (g.cells[axis] - 0.5);
    EXPECT_NEAR(interpolateCellCentres(f, g, p), interpolateCellCentres(f, g, edge), 1e-12)
        << "axis " << axis;
  }
}

}  // namespace
}  // namespace fluidsound::sim
