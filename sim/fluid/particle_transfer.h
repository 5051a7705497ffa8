// sim/fluid/particle_transfer.h — moving velocity between particles and the MAC grid: APIC (Jiang et
// al. 2015) by default, FLIP/PIC blend (Zhu & Bridson 2005) selectable; trilinear weights.
#pragma once

#include <array>
#include <vector>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particles.h"
#include "sim/fluid/fluid_scene.h"

namespace fluidsound::sim {

/// Where each cell's particles are after sortParticlesByCell: cell c (index (k·nj + j)·ni + i)
/// holds particles [start[c], start[c+1]); start[cells] … size() are outside the grid.
struct CellIndex {
  std::vector<std::size_t> start;
};

/// The sums of one face during particlesToGrid: Σ w·v [m/s] and Σ w (trilinear weights).
struct FaceSum {
  double momentum = 0.0, weight = 0.0;
};

/// Buffers the transfers reuse from substep to substep, so that a substep allocates and clears
/// no particle- or grid-sized array (a solver keeps one; the functions size it to the grid).
struct TransferWorkspace {
  CellIndex index;                          ///< the last sort's index
  std::vector<std::size_t> cellOfParticle;  ///< sort key per particle
  std::vector<std::size_t> order;           ///< sorted position → old position
  Particles sorted;                         ///< the particles' previous arrays, reused
  /// Σ w·v and Σ w per face of each component; all zero between calls of particlesToGrid.
  std::array<std::vector<FaceSum>, 3> faceSums;
};

/// @brief Sorts particles by cell (z, then y, then x; stable), so that transfers visit memory in
///        order and parallel scatters can be split into slabs. Particles outside the grid go last.
CellIndex sortParticlesByCell(Particles& particles, const GridGeometry& grid);
/// @brief As above, with buffers kept in `workspace`; the index returned lives in the workspace
///        until its next sort.
const CellIndex& sortParticlesByCell(Particles& particles, const GridGeometry& grid, TransferWorkspace& workspace);

/// @brief Particle → grid: face velocity = Σ w·(v_p + C_p·(x_face − x_p)) / Σ w (APIC; FLIP/PIC
///        drops the affine term). Faces no particle reaches get velocity 0 and weight 0.
///        Particles must be sorted by cell (sortParticlesByCell). Deterministic for any thread
///        count: z-slabs of 4 cells are scattered in two passes (even, then odd slabs).
/// @param weight  out: Σ w per face, the mass a face received (0 = no liquid nearby)
void particlesToGrid(const Particles& particles, const GridGeometry& grid, TransferScheme scheme,
                     MacVelocity& velocity, std::array<Array3f, 3>& weight);
/// @brief As above, with buffers kept in `workspace` between calls (same result, bit for bit).
void particlesToGrid(const Particles& particles, const GridGeometry& grid, TransferScheme scheme,
                     MacVelocity& velocity, std::array<Array3f, 3>& weight, TransferWorkspace& workspace);

/// @brief Grid → particle. APIC: v_p = u(x_p), C_p,a = Σ u_a,i ∇w_i. FLIP: v_p ← r·(v_p +
///        u(x_p) − u_old(x_p)) + (1 − r)·u(x_p), r = settings.flipRatio.
void gridToParticles(Particles& particles, const MacVelocity& velocity, const MacVelocity& oldVelocity,
                     const GridGeometry& grid, const SolverSettings& settings);

/// @brief Trilinear interpolation of the MAC velocity at world position p [m/s].
Vec3 interpolateVelocity(const MacVelocity& velocity, const GridGeometry& grid, const Vec3& p);

}  // namespace fluidsound::sim
