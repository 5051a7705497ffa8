// sim/fluid/particle_neighbourhoods.h — where the particles leave no doubt: per cell, whether the block
// of cells around it is all full of particles, or holds any. Read by the particle surface (its
// interior shortcut) and by the liquid level set (its certain liquid and certain air).
#pragma once

#include <cstddef>
#include <cstdint>

#include "sim/fluid/array3.h"
#include "sim/fluid/particle_transfer.h"

namespace fluidsound::sim {

/// Bits of particleNeighbourhoods.
inline constexpr std::uint8_t kNeighbourhoodFull = 1;  ///< every cell of the block holds ≥ count
inline constexpr std::uint8_t kNeighbourhoodAny = 2;   ///< some cell of the block holds a particle

/// @brief Per cell, over the cube of cells within `radius` of it on each axis: kNeighbourhoodFull
///        when the whole cube lies inside the grid and each of its cells holds at least `count`
///        particles, kNeighbourhoodAny when any of its cells inside the grid holds one. Separable
///        passes along x, y and z (an erosion and a dilation of the per-cell flags).
/// @param index  the particles' cell index (sortParticlesByCell)
/// @param cells  the grid's cell counts
Array3<std::uint8_t> particleNeighbourhoods(const CellIndex& index, const Index3& cells,
                                            std::size_t count, int radius);

}  // namespace fluidsound::sim
