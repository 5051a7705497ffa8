// sim/particle_matching.h — ids for a cache's particles when the cache has none (issue 21;
// docs/import.md): a particle of the next frame is the particle of this frame whose position,
// advected through the liquid's velocity between the two frames, lies nearest to it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particles.h"

namespace fluidsound::sim {

/// @brief Where each particle at `from` is after `dt` [s] in the velocity that goes linearly from
///        `velocityFrom` to `velocityTo` over the step: the midpoint rule (RK2), x + dt·u(x_half,
///        t + dt/2) with x_half = x + dt/2·u(x, t).
std::vector<Vec3f> carriedPositions(std::span<const Vec3f> from, const MacVelocity& velocityFrom,
                                   const MacVelocity& velocityTo, const GridGeometry& grid, double dt);

/// @brief The id of each particle of `next`: that of the particle of `predicted` (the previous
///        frame's particles advected to this frame, with ids `previousIds`) nearest to it within
///        `radius` [m], pairs taken nearest first so that no id is given twice (ties: the lower
///        index first); a particle with none in reach gets a new id, nextId and up.
/// @param nextId  the first unused id; on return the next unused one
/// @note Deterministic: the result depends only on the arrays' contents and order.
std::vector<std::uint64_t> matchParticleIds(std::span<const Vec3f> predicted,
                                            std::span<const std::uint64_t> previousIds,
                                            std::span<const Vec3f> next, double radius,
                                            std::uint64_t& nextId);

}  // namespace fluidsound::sim
