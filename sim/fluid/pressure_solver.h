// sim/fluid/pressure_solver.h — pressure projection of the liquid solver: makes the MAC velocity
// divergence-free in the liquid with the variational solid weights of Batty, Bertails & Bridson
// (2007) and a ghost-fluid free surface (Gibou et al. 2002; Enright, Nguyen, Gibou & Fedkiw 2003).
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <vector>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/mic0_preconditioner.h"
#include "sim/fluid/multigrid_preconditioner.h"
#include "sim/fluid/pcg_solver.h"

namespace fluidsound::sim {

/// Lower clamp of the ghost-fluid fraction θ (the liquid part of the segment between a liquid
/// and an air cell centre). The surface coefficient weight/θ is then at most 100× a full face, so
/// the matrix stays well conditioned when the surface passes within h/100 of a cell centre, where
/// the pressure is ≈ 0 anyway (the value Batty's Fluid3D uses).
inline constexpr double kMinimumSurfaceFraction = 0.01;

/// θ across an open face of the domain (a face with weight > 0 on the grid's boundary): the
/// exterior is air, and p = 0 on the boundary face itself, half a cell from the liquid cell's
/// centre; liquid that crosses it is deleted (DESIGN.md, domain `open`).
inline constexpr double kOpenBoundarySurfaceFraction = 0.5;

/// Preconditioner of the pressure solve's conjugate gradients.
enum class Preconditioner {
  Mic0,       ///< modified incomplete Cholesky (Bridson 2015, ch. 5); serial triangular solves
  Multigrid,  ///< one geometric multigrid V-cycle (McAdams, Sifakis & Teran 2010); needs the grid
};

/// Settings of the pressure solve (filled from SolverSettings::pressureTolerance and
/// maxPressureIterations).
struct PressureSettings {
  double tolerance = 1e-6;   ///< stop when max|r| ≤ tolerance·max|b| (relative, max-norm)
  int maxIterations = 1000;  ///< PCG iteration limit
  /// Multigrid by default (McAdams et al. 2010: 11–23 CG iterations from 32³ to 128³ where MIC(0)
  /// needs 34–122; 1.2–1.8× faster per projection from 64³ up); MIC(0) selectable.
  Preconditioner preconditioner = Preconditioner::Multigrid;
  bool operator==(const PressureSettings&) const = default;
};

/// What a projection did (recorded per frame in report.json: cg_iterations, cg_residual).
struct PressureReport {
  int iterations = 0;            ///< PCG iterations
  double relativeResidual = 0;   ///< max|r| / max|b| at exit
  bool converged = false;        ///< relativeResidual ≤ settings.tolerance
  std::int64_t unknowns = 0;     ///< liquid cells with at least one open face
  int matrixVectorProducts = 0;  ///< 7-point products evaluated
  double matvecEquivalents = 0;  ///< products plus preconditioner work (PcgResult)
  /// pockets of liquid sealed by solids on every side, solved with their volume held (sealPockets)
  std::int64_t sealedPockets = 0;
  bool operator==(const PressureReport&) const = default;
};

std::ostream& operator<<(std::ostream& out, const PressureReport& report);

/// What one projection solves (views: the caller keeps the arrays alive during the call).
struct PressureProblem {
  /// Signed distance to the liquid surface at cell centres [m], < 0 inside the liquid; size
  /// grid.cells.
  const Array3f& liquidPhi;
  /// Open fraction [0, 1] per axis, size grid.faceCount(axis) (SolidBoundary::faceOpen).
  const std::array<Array3f, 3>& faceOpen;
  /// Solid velocity [m/s] per axis (SolidBoundary::faceVelocity; zero arrays for static solids).
  const std::array<Array3f, 3>& solidVelocity;
  const GridGeometry& grid;
  double density = 0.0;  ///< ρ [kg/m³], > 0
  double dt = 0.0;       ///< Δt [s], > 0
  /// If given, the divergence [1/s] each liquid cell should have after the projection instead
  /// of 0 (size grid.cells): divergence control (Kim et al. 2007), used for the particle density
  /// correction.
  const Array3f* targetDivergence = nullptr;
};

/// @brief The pressure projection (Batty, Bertails & Bridson 2007; Bridson 2015, ch. 5).
///
/// Unknowns are the liquid cells (liquidPhi < 0) with at least one face of weight > 0. For a face
/// f of weight w_f (open fraction) between cells c and n the matrix gets w_f·Δt/(ρh²) on the
/// diagonal of c and −w_f·Δt/(ρh²) between c and n when n is liquid; when n is air the ghost-fluid
/// condition p = 0 on the surface adds w_f·Δt/(ρh²)/θ to the diagonal, θ = φ_c/(φ_c − φ_n)
/// clamped below by kMinimumSurfaceFraction. The right-hand side is the negated weighted
/// divergence −(1/h)·Σ_f ±[w_f·u_f + (1 − w_f)·u_solid,f]. After the solve, every face with
/// w_f > 0 next to liquid gets u_f −= Δt/(ρh)·(p_+ − p_−)/θ (θ = 1 between liquid cells, air at
/// p = 0) and is marked valid; faces with w_f = 0 get the solid velocity, faces with no liquid on
/// either side keep their value; both are marked invalid. A face with w_f > 0 on the grid's
/// boundary (an open domain face) has air beyond it, p = 0 on the face (θ = ½,
/// kOpenBoundarySurfaceFraction).
///
/// @par Example: hydrostatic tank
/// @code
///   air (p = 0) ─ ─ ─ ─ ─ ─ ─ ─   surface y = H (liquidPhi = y − H)
///   │  liquid: v* = −gΔt       │  p(y) = ρ g (H − y) exactly, v = 0 after projection
///   └──────────────────────────┘  walls: weight 0, u_solid = 0
/// @endcode
/// @note Starts every solve from p = 0, so the result depends only on the inputs; bit-identical
///       for any thread count (see PcgSolver). A liquid region with no air neighbour gives a
///       singular (pure Neumann) block: CG still converges when its right-hand side sums to zero,
///       as it does for static or rigidly moving solids.
class PressureSolver {
 public:
  /// @brief Projects `velocity` (face velocities [m/s], updated in place) as `problem` says.
  /// @throws std::invalid_argument if an array's size does not match the grid, or ρ, Δt or h ≤ 0
  PressureReport project(MacVelocity& velocity, const PressureProblem& problem,
                         const PressureSettings& settings);

  /// Cell-centred pressure [Pa] of the last projection, relative to the air (p = 0); 0 in cells
  /// that were not unknowns. Size grid.cells.
  const Array3d& pressure() const { return pressure_; }

  /// Per axis, 1 on faces whose velocity the last projection computed (weight > 0, liquid on at
  /// least one side), 0 elsewhere: extrapolate into the 0 faces before advection reads them.
  const std::array<Array3<std::uint8_t>, 3>& validFaces() const { return valid_; }

 private:
  /// Numbers the unknowns and fills matrix_ and rhs_.
  void assemble(const MacVelocity& velocity, const PressureProblem& problem);
  /// Makes each sealed pocket of liquid (no cell next to air or an open face) solvable: its
  /// right-hand side's mean removed, its first cell pinned. @return the pockets found
  std::int64_t sealPockets(const std::vector<std::uint8_t>& fixedLevel, double scale);
  /// The pressure gradient on the open faces next to liquid; valid_.
  void updateVelocity(MacVelocity& velocity, const PressureProblem& problem);

  Array3<std::int32_t> unknownOfCell_;  ///< unknown number per cell, −1 if none
  SevenPointMatrix matrix_;
  std::vector<double> rhs_;
  std::int64_t sealedPockets_ = 0;  ///< of the last assemble()
  std::vector<double> solution_;
  PcgSolver pcg_;
  Mic0Preconditioner mic0_;            ///< rebuilt by every solve that uses it
  MultigridPreconditioner multigrid_;  ///< rebuilt by every solve that uses it
  Array3d pressure_;
  std::array<Array3<std::uint8_t>, 3> valid_;
};

/// @brief Largest relative divergence max_c |Σ_f ±[w_f·u_f + (1 − w_f)·u_solid,f]| / max|u| over
///        liquid cells with an open face (the discrete weighted divergence of the projection,
///        times h, divided by the largest |u| on the faces of those cells, or by `speedFloor` [m/s]
///        if that is larger). The acceptance test asks for < 1e-4. 0 when there is no liquid.
///        The solver's floor is |g|·Δt, the speed its substep's forces add: liquid at rest leaves
///        round-off velocities whose ratio to each other means nothing.
double maxRelativeDivergence(const MacVelocity& velocity, const Array3f& liquidPhi,
                             const std::array<Array3f, 3>& faceOpen,
                             const std::array<Array3f, 3>& solidVelocity, const GridGeometry& grid,
                             double speedFloor = 0.0);

/// @brief maxRelativeDivergence for static solids (u_solid = 0).
double maxRelativeDivergence(const MacVelocity& velocity, const Array3f& liquidPhi,
                             const std::array<Array3f, 3>& faceOpen, const GridGeometry& grid);

}  // namespace fluidsound::sim
