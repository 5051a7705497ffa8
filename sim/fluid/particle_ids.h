// sim/fluid/particle_ids.h — stable particle identities for the bubble model: a particle keeps its id
// through every sort, deletion and reseeding, so per-particle records (entrainment tags, seeds)
// can follow it from substep to substep; new particles get fresh ids in array order.
#pragma once

#include <cstdint>
#include <limits>
#include <span>

namespace fluidsound::sim {

/// The id of a particle that has not been numbered yet (added by seeding, reseeding or emission).
inline constexpr std::uint64_t kUnassignedParticleId = std::numeric_limits<std::uint64_t>::max();

/// @brief Numbers every unassigned id in array order: next, next + 1, … (and advances `next`).
///        The solver's arrays are in a deterministic order, so ids are the same for any thread
///        count. Call after every operation that adds particles.
/// @return how many ids were assigned
inline std::size_t assignParticleIds(std::span<std::uint64_t> ids, std::uint64_t& next) {
  std::size_t assigned = 0;
  for (std::uint64_t& id : ids)
    if (id == kUnassignedParticleId) id = next++, ++assigned;
  return assigned;
}

}  // namespace fluidsound::sim
