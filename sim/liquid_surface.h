// sim/liquid_surface.h — the liquid's signed distance at cell centres, from the particles
// (Zhu & Bridson 2005, "Animating sand as a fluid": kernel-averaged particle position and radius).
#pragma once

#include "sim/array3.h"
#include "sim/grid.h"
#include "sim/particle_transfer.h"
#include "sim/particles.h"

namespace fluidsound::sim {

/// @brief φ(x) = |x − x̄(x)| − r, x̄ = Σ k_p x_p / Σ k_p, k_p = max(0, 1 − |x − x_p|²/R²)³,
///        R = 1.5 cells, over the particles of the 3×3×3 cells around x;
///        negative inside the liquid [m]. Where no particle is within R, φ = R·kFarFactor.
/// @param particles     sorted by cell (index from sortParticlesByCell)
/// @param particleRadius r [m] (the solver uses 0.8 × the particle spacing h/∛particlesPerCell)
Array3f liquidDistanceFromParticles(const Particles& particles, const CellIndex& index,
                                    const GridGeometry& grid, double particleRadius);

/// @brief Volume of liquid [m³] from φ at cell centres: cells with |φ| ≥ h count whole or not
///        at all; the others by 4 × 4 × 4 samples of φ interpolated between centres, each
///        clamp(½ − φ/(h/4), 0, 1) liquid. Sampling, not clamp(½ − φ/h) at the centre: the
///        particle surface's φ is a distance only near the surface and a plateau ≈ −0.4 h inside,
///        which the centre formula would count as 0.9 of a cell.
double liquidVolume(const Array3f& phi, const GridGeometry& grid);

}  // namespace fluidsound::sim
