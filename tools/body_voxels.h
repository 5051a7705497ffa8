// tools/body_voxels.h — a body's closed triangle mesh as the voxels its modal analysis runs on:
// the cells of a cubic grid whose centres lie inside the mesh (signed distance < 0, OpenVDB's
// mesh-to-volume through sim/fluid/mesh_distance.h).
#pragma once

#include <string>

#include "acoustics/modal/voxel_solid.h"
#include "sim/fluid/triangle_mesh.h"

namespace fluidsound::tools {

/// @brief The voxels of `mesh` scaled by `scale` about the origin: `resolution` cells along the
///        longest side of its bounding box, the grid's corner at the box's minimum.
/// @throws std::invalid_argument for scale ≤ 0 or resolution < 2
/// @return the solid; empty cells when the body is thinner than a voxel everywhere
acoustics::VoxelSolid voxeliseBody(const sim::TriangleMesh& mesh, double scale, int resolution);

/// @brief Why the voxels cannot carry the body's modes, or empty when they can: no voxel centre
///        inside (the body thinner than a voxel everywhere). One voxel through a wall is enough
///        for its bending: the elements carry incompatible modes (hex_element.h).
std::string voxelResolutionProblem(const acoustics::VoxelSolid& solid, int resolution);

}  // namespace fluidsound::tools
