// sim/fluid/density_correction.h — moving particles from where they have bunched up to where they have
// thinned out, so the liquid keeps its volume: particles advected through the interpolated grid
// velocity drift together near walls and corners (the interpolated field is not exactly
// divergence-free), and the surface built from them then loses volume (docs/solver.md).
// A position correction in the manner of Kugelstadt, Longva, Thuerey & Bender (2019, "Implicit
// density projection for volume conserving liquids"): a Poisson solve for a displacement whose
// divergence is the density excess; positions move, velocities do not.
#pragma once

#include <array>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/particle_advection.h"
#include "sim/fluid/particle_transfer.h"
#include "sim/fluid/particles.h"
#include "sim/fluid/pressure_solver.h"
#include "sim/fluid/solid_boundary.h"

namespace fluidsound::sim {

/// @brief ρ/ρ₀ per cell: Σ over particles of the trilinear weight of the particle at the cell
///        centre, ÷ `perCell` [-]; 1 inside a liquid seeded at `perCell` per cell.
/// @param particles  sorted by cell, `index` from that sort
Array3f relativeParticleDensity(const Particles& particles, const CellIndex& index, const GridGeometry& grid,
                                int perCell);

/// What one correction did.
struct DensityCorrectionReport {
  PressureReport solve;
  double maxExcess = 0.0;  ///< largest ρ/ρ₀ − ρ_expected before the correction [-]
  std::size_t particlesDeleted = 0;  ///< moved through an open domain face
};

/// The liquid a correction reads (views: the caller keeps the arrays alive during the call).
struct DensityCorrectionInput {
  /// The liquid distance the pressure solve uses (extended into solids) [m].
  const Array3f& pressurePhi;
  /// The particles' own surface (liquid_surface.h) [m].
  const Array3f& particlePhi;
  /// Particles per cell of the seeding (ρ/ρ₀ = 1).
  int perCell = 8;
  /// [s] where the mesh solids are placed (the correction is instantaneous).
  double solidTime = 0.0;
};

/// @brief Moves the particles by D = −∇q, the displacement [m] whose divergence in each liquid
///        cell is the target strain s = ρ/ρ₀ − ρ_expected beyond a dead band of ±0.25 (the noise
///        of jittered particles is left alone): too dense spreads, too thin draws in.
///        ρ_expected is what evenly spread particles would read there given the particles'
///        surface φ and the scene's solids (1 inside, 7/8 half a cell below a flat surface or
///        beside a flat solid), so a uniform liquid is left alone at its surface and against
///        solids, and liquid beside a solid is kept as dense as elsewhere (else particles keep a
///        gap from solids and a submerged solid displaces more than its volume); cells inside
///        solids are skipped. q = 0 on the free surface (ghost fluid), no flux through
///        solids: the pressure projection's operator with a target divergence. D is extended two
///        cells beyond the liquid, set to 0 on closed faces, and the particles move by the
///        midpoint rule, pushed out of solids like advection. Velocities are not changed.
/// @param solids    the solids and the grid: a move that would cross a mesh wall stops at it
/// @param settings  the solve's tolerance (a loose one, ~1e-3, is enough: this is a correction
///                  that repeats every frame)
DensityCorrectionReport correctParticleDensity(Particles& particles, const CellIndex& index,
                                               const DensityCorrectionInput& liquid,
                                               const SolidBoundary& solids, PressureSolver& solver,
                                               const PressureSettings& settings);

}  // namespace fluidsound::sim
