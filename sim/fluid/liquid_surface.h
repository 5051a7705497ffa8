// sim/fluid/liquid_surface.h — the liquid's signed distance at cell centres, from the particles
// (Zhu & Bridson 2005, "Animating sand as a fluid": kernel-averaged particle position and radius).
#pragma once

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/particle_transfer.h"
#include "sim/fluid/particles.h"

namespace fluidsound::sim {

/// φ where no particle is within the kernel's reach, in particle radii (liquidDistanceFromParticles):
/// only the sign and the values next to the surface matter to the ghost-fluid pressure solve.
inline constexpr double kParticleSurfaceFarFactor = 1.0;

/// @brief φ(x) = |x − x̄(x)| − r, x̄ = Σ k_p x_p / Σ k_p, k_p = max(0, 1 − |x − x_p|²/R²)³,
///        R = 1.5 cells, over the particles of the 3×3×3 cells around x;
///        negative inside the liquid [m]. Where no particle is within R, φ = r·kParticleSurfaceFarFactor.
///        Deep inside — every cell within 2 cells (each axis) of x inside the grid and holding
///        at least `interiorCount` particles — φ = −r without the sum: in a uniform liquid the
///        kernel mean is within ~0.06 h of x there (tests/sim/fluid/particle_transfer_test.cpp), and
///        what reads φ reads the same bits (the pressure solve its sign, the volume and density
///        samples values that saturate below −h/8 and −h/4, the bubble model's surface distance
///        the cells next to the surface). Where the particles inside are uneven enough to shift
///        the mean by > h/8 the sum would read a shallower liquid than there is; −r reads it as
///        the liquid it is (the dam break: bit-identical to the full sum through frame 18, then
///        the liquid volume differs by 2e-6).
/// @param particles     sorted by cell (index from sortParticlesByCell)
/// @param particleRadius r [m] (the solver uses 0.8 × the particle spacing h/∛particlesPerCell)
/// @param interiorCount  particles per cell that count as full (the solver: half the seeding
///                       count); 0 sums every cell
Array3f liquidDistanceFromParticles(const Particles& particles, const CellIndex& index,
                                    const GridGeometry& grid, double particleRadius,
                                    std::size_t interiorCount = 0);

/// Particles per cell that count as a full cell at a seeding of `particlesPerCell`: half, rounded up
/// (the kernel's interior shortcut, the level set's certain-liquid rule).
std::size_t fullCellParticles(int particlesPerCell);

/// @brief The solver's surface from its particles: liquidDistanceFromParticles with
///        fullCellParticles as full, and every cell holding 1.5× the seeding count (rounded up)
///        at least 0.1 cell inside the liquid whatever the kernel says. The solver makes it every
///        substep; the import of a cache (sim/cache_bubbles.h) the same way.
/// @param particles  sorted by cell (index from sortParticlesByCell)
Array3f solverSurfaceFromParticles(const Particles& particles, const CellIndex& index, const GridGeometry& grid,
                                   double particleRadius, int particlesPerCell);

/// @brief Volume of liquid [m³] from φ at cell centres: cells with |φ| ≥ h count whole or not
///        at all; the others by 4 × 4 × 4 samples of φ interpolated between centres, each
///        clamp(½ − φ/(h/4), 0, 1) liquid. Sampling, not clamp(½ − φ/h) at the centre: the
///        particle surface's φ is a distance only near the surface and a plateau ≈ −0.4 h inside,
///        which the centre formula would count as 0.9 of a cell.
/// @param solidNodes  if given, solid signed distance at the nodes [m]: samples inside a solid
///                    count as no liquid (cells with a node within h of a solid are sampled)
double liquidVolume(const Array3f& phi, const GridGeometry& grid, const Array3f* solidNodes = nullptr);

}  // namespace fluidsound::sim
