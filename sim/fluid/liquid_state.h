// sim/fluid/liquid_state.h — bubble model input: a read-only view of the liquid solver's state at the
// end of a step (particles with stable ids, liquid and solid distances, grid velocity); no copies.
#pragma once

#include <cstdint>
#include <span>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particles.h"

namespace fluidsound::sim {

/// The liquid as the bubble model reads it. Views into the solver's arrays: valid for the call
/// they are passed to only.
/// @par Example (inside the solver, after a substep)
/// @code
///   bubbles.step(LiquidState{particles_.position, particles_.velocity, particles_.id, liquidPhi_,
///                            velocity_, work_->solidNodes, grid_}, time_, dt);
/// @endcode
struct LiquidState {
  std::span<const Vec3f> particlePositions;   ///< [m], world space
  std::span<const Vec3f> particleVelocities;  ///< [m/s], one per particle
  /// One per particle, unique, and the same for a particle from step to step whatever the solver
  /// does to the arrays' order (sorting, deletion, reseeding): the key of its entrainment record.
  std::span<const std::uint64_t> particleIds;
  /// φ at cell centres [m], negative inside the liquid; size grid.cells. BubbleModel::step takes
  /// the solver's field (a distance only near the surface) and redistances it
  /// (liquid_distance.h); detectEntrainment and spawnBubbles expect that true signed distance.
  const Array3f& liquidDistance;
  const MacVelocity& velocity;       ///< grid velocity that moved the liquid over the step [m/s]
  const Array3f& solidNodeDistance;  ///< solid signed distance at nodes [m], negative inside; size grid.nodeCount()
  const GridGeometry& grid;
};

/// @brief Checks that the arrays of `liquid` agree with each other and with its grid.
/// @throws std::invalid_argument naming the first mismatching field and both sizes
void validateLiquidState(const LiquidState& liquid);

}  // namespace fluidsound::sim
