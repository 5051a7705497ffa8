// sim/fluid/cell_interpolation.h — reading a cell-centred grid field (such as the liquid distance φ) at
// any world position: the trilinear interpolant through the cell centres and its gradient.
#pragma once

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"

namespace fluidsound::sim {

/// @brief The 8 cell centres around a world position p [m] and the field's values there, so that
///        the interpolant's value and its gradient come from one set of loads. Outside the hull of
///        the cell centres the field is extended as a constant (positions are clamped).
class CellCentreStencil {
 public:
  /// @param field  one value per cell, size grid.cells
  CellCentreStencil(const Array3f& field, const GridGeometry& grid, const Vec3& p);
  /// The trilinear interpolant: x interpolated first, then y, then z (7 lerps).
  double value() const;
  /// Its exact gradient [field unit / m]: piecewise constant along each axis within a cell, zero
  /// along an axis where p is clamped.
  Vec3 gradient() const;

 private:
  float corner_[8];  ///< corner c at (c & 1, c >> 1 & 1, c >> 2 & 1) steps from the base centre
  double frac_[3];   ///< p's fraction of a cell beyond the base centre, per axis
  bool inside_[3];   ///< false along an axis where p was clamped
  double cellSize_;  ///< [m]
};

/// @brief Trilinear interpolation of a cell-centred field at world position p [m]; outside the
///        hull of the cell centres the field is extended as a constant (positions are clamped).
/// @param field  one value per cell, size grid.cells
double interpolateCellCentres(const Array3f& field, const GridGeometry& grid, const Vec3& p);

}  // namespace fluidsound::sim
