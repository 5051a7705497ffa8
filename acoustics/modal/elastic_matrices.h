// acoustics/modal/elastic_matrices.h — the global stiffness and mass of a voxel solid's hexahedral
// mesh, the two matrices of the modal eigenproblem K x = ω² M x (shared solids.md §1.2, §3.2).
#pragma once

#include <span>
#include <vector>

#include <Eigen/SparseCore>

#include "acoustics/modal/solid_material.h"
#include "acoustics/modal/voxel_solid.h"

namespace fluidsound::acoustics {

/// K and M over the free DOFs of a mesh. A node's DOFs are 3·node + c (c = x, y, z: interleaved);
/// clamped nodes' DOFs are removed and the rest keep their order.
struct ElasticMatrices {
  Eigen::SparseMatrix<double> stiffness;  ///< K [N/m], symmetric, both triangles stored
  Eigen::SparseMatrix<double> mass;       ///< M [kg], consistent, symmetric positive definite
  /// For each kept DOF (row of K), its node DOF 3·node + c in the unclamped numbering; ascending.
  std::vector<int> nodeDofs;
};

/// @brief Assembles K and M of `mesh` from hex_element.h's element matrices (one cube, computed
///        once), then removes the DOFs of `clampedNodes` (fixed displacement zero).
/// @param material      E, ν and ρ are used; damping is not
/// @param clampedNodes  node indices of `mesh`, any order, duplicates allowed; none: a free body
/// @note Deterministic: each entry is summed over elements in the mesh's element order.
ElasticMatrices assembleElasticMatrices(const HexMesh& mesh, const SolidMaterial& material,
                                        std::span<const int> clampedNodes = {});

}  // namespace fluidsound::acoustics
