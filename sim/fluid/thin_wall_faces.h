// sim/fluid/thin_wall_faces.h — pressure projection input for walls thinner than a cell: the
// variational face weights come from the solid distance at the grid nodes, which does not see a
// wall lying between two node planes (a 2 mm glass in 5 mm cells), so liquid on one side would be
// coupled through the face to the cell on the other. A ray between the two cell centres finds
// the wall whatever its thickness (docs/solver.md, "Thin walls").
#pragma once

#include <array>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/solid_mesh_rays.h"

namespace fluidsound::sim {

/// @brief Sets the weight of a MAC face to 0 (closed) when the segment between the centres of
///        its two cells crosses a mesh solid's surface (SolidMeshRays::crosses at `time`) while
///        the nodal distance, interpolated at both centres (the mean of each cell's 8 corners),
///        says both are outside solids. Where a centre reads inside, the wall is resolved by the
///        grid and the face keeps its variational weight (a partly covered face of a thick
///        solid must stay partly open, or liquid would not rest flat against a sloped mesh).
/// @param faceOpen           faceOpenFractions(solidNodes, grid), changed in place
/// @param solidNodeDistance  the nodal distance those weights came from [m]
/// @return the number of faces closed
std::size_t closeFacesAcrossThinWalls(std::array<Array3f, 3>& faceOpen, const Array3f& solidNodeDistance,
                                      const SolidMeshRays& meshes, const GridGeometry& grid, double time);

}  // namespace fluidsound::sim
