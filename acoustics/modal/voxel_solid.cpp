// acoustics/modal/voxel_solid.cpp — see voxel_solid.h.
#include "acoustics/modal/voxel_solid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

namespace fluidsound::acoustics {
namespace {

/// A size within this fraction of a cell of a whole number of cells counts as whole (rounding).
constexpr double kWholeCellTolerance = 1e-6;

/// Sorts and removes duplicates in lexicographic (i, j, k) order.
void sortUnique(std::vector<Eigen::Vector3i>& indices) {
  std::sort(indices.begin(), indices.end(), gridIndexLess);
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
}

/// Position of `index` in the sorted `indices`, or −1 when absent.
int findIndex(const std::vector<Eigen::Vector3i>& indices, const Eigen::Vector3i& index) {
  const auto it = std::lower_bound(indices.begin(), indices.end(), index, gridIndexLess);
  if (it == indices.end() || *it != index) return -1;
  return static_cast<int>(it - indices.begin());
}

}  // namespace

bool gridIndexLess(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
  return std::tie(a.x(), a.y(), a.z()) < std::tie(b.x(), b.y(), b.z());
}

VoxelSolid voxelBox(const Eigen::Vector3d& size, double voxelSize) {
  if (!(voxelSize > 0.0)) throw std::invalid_argument("voxelBox: voxelSize must be > 0");
  Eigen::Vector3i count;
  for (int axis = 0; axis < 3; ++axis) {
    const double cells = size[axis] / voxelSize;
    count[axis] = static_cast<int>(std::lround(cells));
    if (!(count[axis] >= 1) || std::abs(cells - count[axis]) > kWholeCellTolerance)
      throw std::invalid_argument(
          "voxelBox: size[" + std::to_string(axis) + "] = " + std::to_string(size[axis]) +
          " m is not a whole number of cells of " + std::to_string(voxelSize) + " m");
  }
  VoxelSolid solid{voxelSize, Eigen::Vector3d::Zero(), {}};
  solid.cells.reserve(static_cast<std::size_t>(count.prod()));
  for (int i = 0; i < count.x(); ++i)
    for (int j = 0; j < count.y(); ++j)
      for (int k = 0; k < count.z(); ++k) solid.cells.emplace_back(i, j, k);
  return solid;  // generated in lexicographic order already
}

VoxelSolid voxelSolidFromInside(const std::function<bool(const Eigen::Vector3d&)>& inside,
                                const Eigen::Vector3d& min, const Eigen::Vector3d& max,
                                double voxelSize) {
  if (!(voxelSize > 0.0))
    throw std::invalid_argument("voxelSolidFromInside: voxelSize must be > 0");
  if (!((max - min).minCoeff() > 0.0))
    throw std::invalid_argument("voxelSolidFromInside: max must exceed min on every axis");
  Eigen::Vector3i count;
  for (int axis = 0; axis < 3; ++axis)
    count[axis] =
        static_cast<int>(std::ceil((max[axis] - min[axis]) / voxelSize - kWholeCellTolerance));
  VoxelSolid solid{voxelSize, min, {}};
  for (int i = 0; i < count.x(); ++i)
    for (int j = 0; j < count.y(); ++j)
      for (int k = 0; k < count.z(); ++k) {
        const Eigen::Vector3d centre =
            min + voxelSize * (Eigen::Vector3d(i, j, k) + Eigen::Vector3d::Constant(0.5));
        if (inside(centre)) solid.cells.emplace_back(i, j, k);
      }
  return solid;  // generated in lexicographic order already
}

HexMesh hexMesh(const VoxelSolid& solid) {
  HexMesh mesh;
  mesh.elementSize = solid.voxelSize;
  mesh.gridNodes.reserve(8 * solid.cells.size());
  for (const Eigen::Vector3i& cell : solid.cells)
    for (int a = 0; a < 8; ++a)
      mesh.gridNodes.push_back(cell + Eigen::Vector3i(a & 1, (a >> 1) & 1, (a >> 2) & 1));
  sortUnique(mesh.gridNodes);
  mesh.positions.reserve(mesh.gridNodes.size());
  for (const Eigen::Vector3i& node : mesh.gridNodes)
    mesh.positions.push_back(solid.origin + solid.voxelSize * node.cast<double>());
  mesh.elements.reserve(solid.cells.size());
  for (const Eigen::Vector3i& cell : solid.cells) {
    std::array<int, 8> element;
    for (int a = 0; a < 8; ++a)
      element[a] =
          findIndex(mesh.gridNodes, cell + Eigen::Vector3i(a & 1, (a >> 1) & 1, (a >> 2) & 1));
    mesh.elements.push_back(element);
  }
  return mesh;
}

std::vector<SurfaceFace> surfaceFaces(const VoxelSolid& solid, const HexMesh& mesh) {
  std::vector<SurfaceFace> faces;
  for (std::size_t e = 0; e < solid.cells.size(); ++e)
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        Eigen::Vector3i neighbour = solid.cells[e];
        neighbour[axis] += side == 0 ? -1 : 1;
        if (findIndex(solid.cells, neighbour) >= 0) continue;
        // The face's four corners: local nodes whose bit `axis` equals `side`.
        SurfaceFace face;
        face.axis = axis;
        face.side = side == 0 ? -1 : 1;
        int corner = 0;
        for (int a = 0; a < 8; ++a)
          if (((a >> axis) & 1) == side) face.nodes[corner++] = mesh.elements[e][a];
        faces.push_back(face);
      }
  return faces;
}

std::vector<int> surfaceNodes(const VoxelSolid& solid, const HexMesh& mesh) {
  std::vector<int> surface;
  for (const SurfaceFace& face : surfaceFaces(solid, mesh)) surface.insert(surface.end(), face.nodes.begin(), face.nodes.end());
  std::sort(surface.begin(), surface.end());
  surface.erase(std::unique(surface.begin(), surface.end()), surface.end());
  return surface;
}

}  // namespace fluidsound::acoustics
