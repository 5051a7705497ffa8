// acoustics/transfer/water_helmholtz.h — the water side of the geometric transfer (shared
// transfer.md §1–2): (∇² + k_w²) u = 0 in one frame's liquid, u = p_L on the free surface open to
// the air (ghost fluid, Gibou et al. 2002, as the pressure projection does), u = 0 on enclosed air
// pockets, ∂u/∂n = 0 on solids (the projection's variational face weights, Batty et al. 2007).
// Assembled once per frame; factorised once per frequency (UMFPACK sparse LU, the operator is complex
// symmetric and indefinite above the first resonance). docs/transfer.md, "The geometric model".
#pragma once

#include <complex>
#include <cstddef>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/SparseCore>

#include "acoustics/transfer/water_grid.h"

namespace fluidsound::acoustics {

using Complex = std::complex<double>;

/// A point in air where the water side needs the air-side pressure p_L: a surface crossing (the
/// ghost-fluid point between a liquid and an air cell centre) or an air cell centre that a bubble
/// sample's interpolation reads.
struct AirPoint {
  Vec3 position{};        ///< [m], world space
  bool enclosed = false;  ///< in an air pocket closed off from the open air: p_L = 0 there
};

/// u at one point, as an affine map of the unknowns (liquid cell values) and the air points'
/// p_L: u(x) = Σ cells w·u_c + Σ air w·p_L,a. Trilinear over the 8 cell centres around x; a
/// solid corner is dropped and the rest renormalised, an air corner reads p_L at its centre.
struct PointSample {
  std::vector<std::pair<int, double>> cells;  ///< (unknown index, weight)
  std::vector<std::pair<int, double>> air;    ///< (air point index, weight)
};

class HelmholtzFactor;

/// Modes of the water (water_modes.h) that a solve works outside of: Φ (unknowns × J,
/// M-orthonormal columns) and MΦ.
struct ExcludedModes {
  Eigen::MatrixXcd shapes, massShapes;

  ExcludedModes(const Eigen::MatrixXd& modeShapes, const Eigen::VectorXd& mass);
  /// Replaces b by b − MΦ Φᵀb, the part of a right-hand side that excites none of the modes,
  /// and returns the modes' numerators Φᵀb.
  Eigen::VectorXcd deflate(Eigen::VectorXcd& rhs) const;
  /// v − Φ (MΦ)ᵀ v: the part of a field M-orthogonal to the modes.
  void project(Eigen::VectorXcd& field) const;
};

/// How K(ω) is factorised; both give the same u to kRefinementTolerance (a test checks it).
enum class HelmholtzMethod {
  /// A real LDLᵀ (Eigen, AMD ordering) of the lossless operator with the loss added back by
  /// iterative refinement; where that does not converge (within ~η of a resonance) the
  /// reference LU. ~10× faster on the scenes' frames (docs/transfer.md, "Solver").
  Fast,
  /// The complex LU of K(ω) itself (UMFPACK).
  Reference,
};

/// k_w² = (ω/c_w)²(1 − iη) [1/m²]: the water's wavenumber squared with the loss factor η.
inline Complex lossyWavenumberSquared(double angularFrequency, double soundSpeed,
                                      double lossFactor) {
  const double k = angularFrequency / soundSpeed;
  return {k * k, -k * k * lossFactor};
}

/// Relative residual ‖b − K u‖/‖b‖ at which the fast method's refinement stops.
inline constexpr double kRefinementTolerance = 1e-10;
/// Refinement steps before the fast method falls back to the LU.
inline constexpr int kMaxRefinements = 8;

/// One frame's water-side problem: the liquid cells, their weighted Laplacian with the ghost-fluid
/// surface terms and the air points. Independent of frequency.
class WaterHelmholtz {
 public:
  /// @param lossFactor  η ≥ 0: k_w² = (ω/c_w)²·(1 − iη), the physical loss that keeps resonances
  ///                    finite (docs/transfer.md gives the default and its reason)
  /// @throws std::invalid_argument for a grid whose arrays do not match its cell counts
  WaterHelmholtz(const WaterGrid& grid, double soundSpeed, double lossFactor);
  ~WaterHelmholtz();
  WaterHelmholtz(WaterHelmholtz&&) noexcept;
  WaterHelmholtz& operator=(WaterHelmholtz&&) noexcept;

  std::size_t unknowns() const;
  /// h [m] of the frame's grid.
  double cellSize() const;
  /// Points where p_L is needed: every surface crossing, then every air cell centre next to the
  /// liquid (26-neighbourhood), in a fixed order (cell order, then axis).
  const std::vector<AirPoint>& airPoints() const;
  /// World size [m] of the liquid's bounding box diagonal (0 without liquid): D of the band rule.
  double liquidSize() const;
  /// Centre [m] of the liquid's bounding box.
  Vec3 liquidCentre() const;
  /// Whether the cell holding `x` [m] is a liquid unknown.
  bool inLiquid(const Vec3& x) const;
  /// The sample of u at `x` [m]; empty (no cells, no air) when no liquid cell is among its corners.
  PointSample sampleAt(const Vec3& x) const;

  /// @brief Factorises K(ω) = L − k_w² M, k_w² = (ω/c_w)²(1 − i(η + extraLoss)).
  /// @param extraLoss  ≥ 0, added to the frame's loss factor η: a bubble's own damping constant
  ///                   δ where its resonances are broadened by it (docs/transfer.md)
  /// @throws std::runtime_error when the factorisation fails
  std::unique_ptr<HelmholtzFactor> factorise(double angularFrequency,
                                             HelmholtzMethod method = HelmholtzMethod::Fast,
                                             double extraLoss = 0.0) const;
  /// The adjoint source s of a sample: its cells' trilinear weights (K w = s gives u's weights).
  Eigen::VectorXcd pointSource(const PointSample& sample) const;
  /// η, the frame's loss factor.
  double lossFactor() const;

  /// The right-hand side B·p_L of the reciprocal solve from p_L at airPoints() (size must match).
  Eigen::VectorXcd rightHandSide(std::span<const Complex> airPressure) const;
  /// Bᵀw restricted to the air points, plus the sample's own air weights: the weights that turn
  /// one adjoint solution w = K⁻¹s into u(x) = Σ_a weight_a·p_L,a for any p_L.
  std::vector<Complex> airWeights(const PointSample& sample, const Eigen::VectorXcd& adjoint) const;
  /// K(ω) = L − k_w² M: L, the weighted Laplacian with the ghost-fluid diagonal (×h², symmetric,
  /// positive definite wherever the liquid meets air), frequency independent.
  const Eigen::SparseMatrix<double>& stiffness() const;
  /// M's diagonal: each unknown's open volume fraction·h² [m²].
  const Eigen::VectorXd& mass() const;
  /// u(x) from a reciprocal solution `u` and p_L.
  Complex evaluate(const PointSample& sample, const Eigen::VectorXcd& u,
                   std::span<const Complex> airPressure) const;

 private:
  friend class HelmholtzFactor;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// K(ω) factorised: any number of solves at that frequency.
class HelmholtzFactor {
 public:
  ~HelmholtzFactor();
  /// K⁻¹ b. @throws std::runtime_error when the solve fails or gives a non-finite value
  Eigen::VectorXcd solve(const Eigen::VectorXcd& rhs) const;
  /// K⁻¹ b for a b that excites none of `modes` (ExcludedModes::deflate), its iterates kept
  /// outside them: the fast method's refinement then converges at η·k²/(λ − k²) per step, λ the
  /// lowest mode not excluded, however near an excluded resonance ω lies.
  Eigen::VectorXcd solveOutside(const Eigen::VectorXcd& rhs, const ExcludedModes& modes) const;
  /// The adjoint source of a sample: K⁻ᵀ s = K⁻¹ s (K is complex symmetric).
  Eigen::VectorXcd adjoint(const PointSample& sample) const;

 private:
  friend class WaterHelmholtz;
  struct Impl;
  explicit HelmholtzFactor(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace fluidsound::acoustics
