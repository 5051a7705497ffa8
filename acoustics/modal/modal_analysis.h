// acoustics/modal/modal_analysis.h — the modal model of a voxelised elastic solid: the frequencies,
// decay rates and surface shapes of its lowest vibration modes, computed once per object before
// synthesis (shared solids.md §1.1–1.2: modal synthesis after O'Brien 2002; §3.2–3.3).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "acoustics/modal/solid_material.h"
#include "acoustics/modal/voxel_solid.h"

namespace fluidsound::acoustics {

/// What modal analysis keeps.
struct ModalSettings {
  int maxModes = 200;             ///< at most this many elastic modes, the lowest, ≥ 1
  double maxFrequency = 20000.0;  ///< modes of higher undamped frequency are dropped [Hz]
  /// Nodes at positions [m] where this is true are clamped (zero displacement); empty: a free body.
  std::function<bool(const Eigen::Vector3d&)> clamped;
  /// Modes below this undamped frequency are rigid-body motions and are dropped [Hz]: far above
  /// the rigid modes' rounding noise (~√(ε·λ_max)/2π, well under 0.1 Hz for voxels ≥ 1 mm), far
  /// below any audible mode.
  double rigidFrequency = 1.0;
};

/// The modes of a solid, lowest first, with their shapes on its surface.
struct ModalModel {
  std::vector<double> frequency;  ///< undamped f_j = ω_j/2π [Hz], ascending
  std::vector<double> decayRate;  ///< d_j = (a_M + b_K ω_j²)/2 [1/s] (modalDecayRate)
  /// f_d = √(ω_j² − d_j²)/2π [Hz]; 0 for a mode damped critically or more (it does not ring)
  std::vector<double> dampedFrequency;
  std::vector<int> surfaceNodes;                  ///< the mesh nodes on the surface, ascending
  std::vector<Eigen::Vector3d> surfacePositions;  ///< their positions [m]
  /// the surface's squares (h × h, h = voxelSize), their corners as indices into surfaceNodes
  std::vector<SurfaceFace> surfaceFaces;
  double voxelSize = 0.0;  ///< h [m]
  /// (3 · surface nodes) × modes: mode j's displacement at surface node s along axis c is
  /// row 3s + c of column j [1/√kg], from M-orthonormal shapes (φᵀMφ = 1 over all nodes, M the
  /// consistent mass); each shape's sign is arbitrary but fixed.
  Eigen::MatrixXf surfaceShapes;
  int dofCount = 0;                      ///< unknowns of the eigenproblem (3 per free node)
  int rigidModesDropped = 0;             ///< modes below rigidFrequency (6 for a free body)
  std::vector<double> rigidFrequencies;  ///< their signed √λ/2π [Hz] (negative for λ < 0)
  int operations = 0;                    ///< shift-invert solves the Lanczos iteration took

  /// Member by member; the counts compared first make the shape matrices' sizes agree.
  friend bool operator==(const ModalModel&, const ModalModel&) = default;
};

/// @brief Fills `model`'s surface from the solid and its mesh: the surface nodes, their positions,
///        the voxel size and the surface faces with their corners as indices into surfaceNodes.
void setModelSurface(ModalModel& model, const VoxelSolid& solid, const HexMesh& mesh);

/// @brief How mode j moves the surface, per axis: the shares of Σ_s |φ_j(s)|² along x, y and z
///        over the surface nodes (they sum to 1): a bar's bending across its thickness is almost
///        all along that axis, a torsion splits between the two across the bar.
std::array<double, 3> surfaceMotionShares(const ModalModel& model, std::size_t mode);

/// @brief The modes of `solid` made of `material`: linear elasticity on the voxels' 8-node
///        hexahedra with incompatible modes (hex_element.h), lowest eigenpairs of K x = ω² M x by
///        shift-invert Lanczos (modal_solve.h), rigid modes dropped, at most settings.maxModes
///        modes up to settings.maxFrequency kept.
/// @note Deterministic: the same bits on every run.
/// @throws std::invalid_argument for an empty solid, a voxel size ≤ 0, an invalid material,
///         maxModes < 1, or not 0 ≤ rigidFrequency < maxFrequency
/// @throws std::runtime_error when the eigensolver fails (modal_solve.h)
ModalModel analyseModes(const VoxelSolid& solid, const SolidMaterial& material,
                        const ModalSettings& settings);

}  // namespace fluidsound::acoustics
