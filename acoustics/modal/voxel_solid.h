// acoustics/modal/voxel_solid.h — a sounding solid as a set of equal cubic voxels, and the
// 8-node hexahedral mesh the modal analysis runs on (shared solids.md §3.2: voxel hexahedral FEM).
// Grid index (i, j, k) names the cell whose corner nearest −∞ is origin + h·(i, j, k), and the
// node at that same point. Cells and nodes are numbered in lexicographic (i, j, k) order.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace fluidsound::acoustics {

/// Lexicographic order on grid indices: i first, then j, then k.
bool gridIndexLess(const Eigen::Vector3i& a, const Eigen::Vector3i& b);

/// A solid made of cubic cells of one size.
struct VoxelSolid {
  double voxelSize = 0.0;                            ///< cell edge h [m], > 0
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< corner of cell (0, 0, 0) [m]
  std::vector<Eigen::Vector3i> cells;                ///< solid cells, sorted, unique
};

/// @brief The box [0, size] tiled exactly by cells of edge voxelSize (origin at 0).
/// @param size       edge lengths [m]; each must be a positive whole multiple of voxelSize
///                   (to 1e-6 of a cell)
/// @param voxelSize  h [m], > 0
/// @throws std::invalid_argument when a size is not a whole number of cells
VoxelSolid voxelBox(const Eigen::Vector3d& size, double voxelSize);

/// @brief The cells of the grid from `min` (origin) covering [min, max] whose centre is inside.
/// @param inside     true for a point [m] inside the solid
/// @param min, max   corners of the region searched [m], max > min on every axis
/// @param voxelSize  h [m], > 0
/// @throws std::invalid_argument for an empty region or a voxel size ≤ 0
VoxelSolid voxelSolidFromInside(const std::function<bool(const Eigen::Vector3d&)>& inside,
                                const Eigen::Vector3d& min, const Eigen::Vector3d& max,
                                double voxelSize);

/// The 8-node hexahedra of a voxel solid, one per cell, sharing nodes at common corners.
struct HexMesh {
  double elementSize = 0.0;                ///< cube edge h [m]
  std::vector<Eigen::Vector3i> gridNodes;  ///< each node's grid index, sorted, unique
  std::vector<Eigen::Vector3d> positions;  ///< each node's position [m]
  /// Each element's nodes in hex_element.h's local order: entry dx + 2·dy + 4·dz is the node at
  /// the cell's grid index + (dx, dy, dz). Elements follow the solid's cells.
  std::vector<std::array<int, 8>> elements;
};

/// The mesh of `solid`'s cells: a node at every cell corner.
HexMesh hexMesh(const VoxelSolid& solid);

/// A cell face that is not shared by two solid cells: a square of the body's surface.
struct SurfaceFace {
  std::array<int, 4> nodes{};  ///< its corners (mesh node indices, or surface-node indices in ModalModel)
  int axis = 0;                ///< its outward normal lies along this axis (0 x, 1 y, 2 z)…
  int side = 1;                ///< …pointing to + (1) or − (−1)
  friend bool operator==(const SurfaceFace&, const SurfaceFace&) = default;
};

/// @brief The solid's surface faces, cell by cell in the solid's order, then −x, +x, −y, … .
///        `mesh` must be hexMesh(solid).
std::vector<SurfaceFace> surfaceFaces(const VoxelSolid& solid, const HexMesh& mesh);

/// @brief The nodes on the solid's surface: corners of a cell face that is not shared by two
///        solid cells. Ascending node indices of `mesh`, which must be hexMesh(solid).
std::vector<int> surfaceNodes(const VoxelSolid& solid, const HexMesh& mesh);

}  // namespace fluidsound::acoustics
