// acoustics/modal/elastic_matrices.cpp — see elastic_matrices.h.
#include "acoustics/modal/elastic_matrices.h"

#include <algorithm>

#include "acoustics/modal/hex_element.h"

namespace fluidsound::acoustics {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// For each node, the nodes it shares an element with (itself included), ascending: the 3 × 3
/// block pattern of both K and M.
std::vector<std::vector<int>> nodeNeighbours(const HexMesh& mesh) {
  std::vector<std::vector<int>> neighbours(mesh.gridNodes.size());
  for (const std::array<int, 8>& element : mesh.elements)
    for (const int a : element)
      neighbours[a].insert(neighbours[a].end(), element.begin(), element.end());
  for (std::vector<int>& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

/// Σ over elements of the element matrix, in compressed column storage over all node DOFs.
SparseMatrix assembled(const HexMesh& mesh, const std::vector<std::vector<int>>& neighbours,
                       const HexElementMatrix& element) {
  const Eigen::Index dofs = 3 * static_cast<Eigen::Index>(neighbours.size());
  SparseMatrix matrix(dofs, dofs);
  // Column 3n + c holds rows 3m + c' for every neighbour m of n, c' = 0, 1, 2.
  std::vector<int> columnStart(static_cast<std::size_t>(dofs) + 1, 0);
  for (std::size_t n = 0; n < neighbours.size(); ++n)
    for (int c = 0; c < 3; ++c)
      columnStart[3 * n + c + 1] =
          columnStart[3 * n + c] + 3 * static_cast<int>(neighbours[n].size());
  matrix.resizeNonZeros(columnStart.back());
  std::copy(columnStart.begin(), columnStart.end(), matrix.outerIndexPtr());
  for (std::size_t n = 0; n < neighbours.size(); ++n)
    for (int c = 0; c < 3; ++c) {
      int* rows = matrix.innerIndexPtr() + columnStart[3 * n + c];
      for (const int m : neighbours[n])
        for (int r = 0; r < 3; ++r) *rows++ = 3 * m + r;
    }
  std::fill(matrix.valuePtr(), matrix.valuePtr() + matrix.nonZeros(), 0.0);
  for (const std::array<int, 8>& nodes : mesh.elements)
    for (int b = 0; b < 8; ++b) {
      const std::vector<int>& column = neighbours[nodes[b]];
      for (int a = 0; a < 8; ++a) {
        const int slot = static_cast<int>(std::lower_bound(column.begin(), column.end(), nodes[a]) -
                                          column.begin());
        for (int cb = 0; cb < 3; ++cb) {
          double* values = matrix.valuePtr() + columnStart[3 * nodes[b] + cb] + 3 * slot;
          for (int ca = 0; ca < 3; ++ca) values[ca] += element(3 * a + ca, 3 * b + cb);
        }
      }
    }
  return matrix;
}

/// The rows and columns of `matrix` listed in `kept` (ascending), renumbered 0, 1, ….
SparseMatrix restricted(const SparseMatrix& matrix, const std::vector<int>& kept,
                        const std::vector<int>& keptIndex) {
  const Eigen::Index size = static_cast<Eigen::Index>(kept.size());
  SparseMatrix result(size, size);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(matrix.nonZeros()));
  for (Eigen::Index column = 0; column < size; ++column)
    for (SparseMatrix::InnerIterator it(matrix, kept[column]); it; ++it)
      if (keptIndex[it.row()] >= 0) entries.emplace_back(keptIndex[it.row()], column, it.value());
  result.setFromTriplets(entries.begin(), entries.end());  // one entry per slot: no sums
  return result;
}

}  // namespace

ElasticMatrices assembleElasticMatrices(const HexMesh& mesh, const SolidMaterial& material,
                                        std::span<const int> clampedNodes) {
  const std::vector<std::vector<int>> neighbours = nodeNeighbours(mesh);
  const double edge = mesh.elementSize;
  ElasticMatrices matrices;
  matrices.stiffness = assembled(
      mesh, neighbours, hexElementStiffness(edge, material.youngsModulus, material.poissonsRatio));
  matrices.mass = assembled(mesh, neighbours, hexElementMass(edge, material.density));
  const int dofs = 3 * static_cast<int>(mesh.gridNodes.size());
  std::vector<bool> clamped(mesh.gridNodes.size(), false);
  for (const int node : clampedNodes) clamped[static_cast<std::size_t>(node)] = true;
  std::vector<int> keptIndex(static_cast<std::size_t>(dofs), -1);
  for (int dof = 0; dof < dofs; ++dof)
    if (!clamped[static_cast<std::size_t>(dof / 3)]) {
      keptIndex[static_cast<std::size_t>(dof)] = static_cast<int>(matrices.nodeDofs.size());
      matrices.nodeDofs.push_back(dof);
    }
  if (static_cast<int>(matrices.nodeDofs.size()) < dofs) {
    matrices.stiffness = restricted(matrices.stiffness, matrices.nodeDofs, keptIndex);
    matrices.mass = restricted(matrices.mass, matrices.nodeDofs, keptIndex);
  }
  return matrices;
}

}  // namespace fluidsound::acoustics
