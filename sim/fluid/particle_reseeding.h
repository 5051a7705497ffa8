// sim/fluid/particle_reseeding.h — keeping 4–16 particles in every liquid cell: FLIP/APIC particles
// drift apart and clump as they follow the grid velocity, and a cell left empty inside the liquid
// reads as air to the surface and the pressure solve (lost volume); a clump wastes work.
#pragma once

#include <cstdint>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particle_advection.h"
#include "sim/fluid/particle_transfer.h"
#include "sim/fluid/particles.h"

namespace fluidsound::sim {

struct ReseedingLimits {
  int minimum = 4;   ///< a liquid cell with fewer particles is refilled to `target`
  int target = 8;    ///< particles per cell after refilling (the seeding density)
  int maximum = 16;  ///< a cell with more keeps its first `maximum` in sorted order
};

/// One reseeding pass: its limits and what makes its random positions.
struct ReseedingPass {
  ReseedingLimits limits;
  std::uint64_t seed = 1;  ///< the scene seed
  std::uint64_t pass = 0;  ///< the pass number (a new stream per pass)
  double solidTime = 0.0;  ///< [s] where the mesh solids are placed
};

/// What one reseeding pass did.
struct ReseedingCount {
  std::size_t added = 0, removed = 0;
};

/// @brief Refills cells inside the liquid (φ at the centre ≤ −h/2: wholly liquid to first order)
///        that hold fewer than limits.minimum particles up to limits.target, at random positions
///        in the cell outside solids (and, in a cell cut by a mesh wall, on the side of the cell's
///        first particle: no ray from it to the new one crosses a mesh surface; an empty cell that
///        a mesh cuts is left empty), with the grid velocity there (affine part zero); thins cells
///        holding more than limits.maximum. New positions come from pass.seed, pass.pass and the
///        cell index, so the result is the same for any thread count.
/// @param particles    sorted by cell, `index` from that sort; still in cell order on return (new
///                     particles follow their cell's kept ones), so `index` is stale
/// @param liquidPhi    liquid signed distance at cell centres [m]
/// @param velocity     the grid velocity (extrapolated beyond the liquid) [m/s]
/// @param solids       the solids (and the grid) at pass.solidTime
ReseedingCount reseedParticles(Particles& particles, const CellIndex& index,
                               const Array3f& liquidPhi, const MacVelocity& velocity,
                               const SolidBoundary& solids, const ReseedingPass& pass);

}  // namespace fluidsound::sim
