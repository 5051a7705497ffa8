// sim/cell_interpolation.h — reading a cell-centred grid field (such as the liquid distance φ) at
// any world position: the trilinear interpolant through the cell centres and its gradient.
#pragma once

#include "sim/array3.h"
#include "sim/grid.h"

namespace fluidsound::sim {

/// A field's value and gradient at one position.
struct FieldSample {
  double value = 0.0;
  Vec3 gradient{0.0, 0.0, 0.0};  ///< [field unit / m]
};

/// @brief Trilinear interpolation of a cell-centred field at world position p [m]; outside the
///        hull of the cell centres the field is extended as a constant (positions are clamped).
/// @param field  one value per cell, size grid.cells
double interpolateCellCentres(const Array3f& field, const GridGeometry& grid, const Vec3& p);

/// @brief The same interpolant's value and exact gradient (piecewise constant along each axis
///        within a cell; zero along an axis where p is clamped).
FieldSample sampleCellCentres(const Array3f& field, const GridGeometry& grid, const Vec3& p);

}  // namespace fluidsound::sim
