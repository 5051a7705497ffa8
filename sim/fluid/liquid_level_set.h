// sim/fluid/liquid_level_set.h — the liquid surface the pressure solve sees: a grid level set carried
// with the liquid and held to the particles, so that still liquid keeps a still surface.
//
// The particles' own surface (liquid_surface.h, Zhu & Bridson 2005) is re-derived from jittered
// positions every substep: its bumps (~0.05 cell) are enough to start gravity waves in a tank at
// rest (docs/solver.md: 2–10 mm/s after 2 s, with the exact flat φ = y − H substituted the tank
// stays at rest to round-off). Here a level set φ at cell centres starts from the scene's liquid
// regions, is advected with the grid velocity (semi-Lagrangian, RK2), and is held to the
// particle surface φ_p: within a band of φ_p ± b, where b shrinks from `bandCells` cells in still
// liquid to 0 at `trustSpeed` (so fast, splashing liquid follows its particles exactly, as the
// particle level set method corrects a grid level set with its particles: Enright, Fedkiw,
// Ferziger & Mitchell 2002, J. Comput. Phys. 183:83 [memory]). Where the particles leave no doubt
// it follows them whatever the band: liquid where every cell around holds particles, air where
// none does.
#pragma once

#include <span>

#include "sim/fluid/array3.h"
#include "sim/fluid/fluid_scene.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particle_transfer.h"
#include "sim/fluid/scene_mesh_distances.h"

namespace fluidsound::sim {

/// A liquid region's face lies against a solid — where the liquid meets the solid, no free
/// surface — where the solid distance at it is at most this [cells]: on a wall or inside it, up
/// to the float rounding of the solid's distance (≈ 1e-5 cell for a mesh wall on the face).
inline constexpr double kSolidContactCells = 0.01;

/// How the level set follows its particles.
struct LevelSetHold {
  double bandCells = 1.0;   ///< b in still liquid [cells]: the particle surface's bumps stay inside
  double trustSpeed = 0.1;  ///< [m/s]: from this speed on, b = 0 (the particles decide alone)
  int fullCount = 4;        ///< particles per cell that count as full (half the seeding count)
};

class LiquidLevelSet {
 public:
  LiquidLevelSet() = default;
  /// @brief φ at cell centres from the scene's liquid regions: their signed distance to their
  ///        free faces, those not lying against a solid or a domain wall (kSolidContactCells;
  ///        water filled up to a tank's walls is y − H deep at the walls too); inside a solid,
  ///        the solid's depth (air: the solid holds no liquid). A mesh region reads
  ///        MeshNodeDistance::freeSurfaceAtCentres (sim/fluid/region_free_surface.h).
  /// @param solidNodes    the solids' signed distance at the nodes, domain walls included [m]
  /// @param regionMeshes  the mesh regions' distances on `grid` (SceneMeshDistances::liquid), one
  ///                      entry per region; may be empty when no region is a mesh
  /// @throws std::invalid_argument for a mesh region whose distance regionMeshes does not hold
  LiquidLevelSet(const FluidScene& scene, const GridGeometry& grid, const Array3f& solidNodes,
                 std::span<const MeshNodeDistance> regionMeshes = {});

  /// @brief Holds φ to the particle surface (see the file comment).
  /// @param particlePhi  the particle surface at cell centres (liquidDistanceFromParticles) [m]
  /// @param index        the particles' cell index (sorted by cell)
  /// @param velocity     the grid velocity the particles carry [m/s]
  /// @param sceneSolidNodes  the scene solids' distance at the nodes (no domain walls) [m]: a
  ///                         cell whose centre is inside one is air (its depth there)
  void holdToParticles(const Array3f& particlePhi, const CellIndex& index,
                       const MacVelocity& velocity, const Array3f& sceneSolidNodes,
                       const LevelSetHold& hold);

  /// @brief Carries φ with `velocity` for dt [s]: φ(x) ← φ(x − dt·u(x − ½dt·u(x))), in the cells
  ///        within `bandCells` of the surface (|φ| < bandCells·h; the surface moves at most the
  ///        CFL number of cells per substep, and further out only φ's sign matters, which the
  ///        particles hold). A cell whose departure point lies inside a scene solid
  ///        (`sceneSolidNodes`, no domain walls) takes the particle surface at the next
  ///        holdToParticles: a solid carries no liquid with it.
  void advect(const MacVelocity& velocity, const Array3f& sceneSolidNodes, double dt,
              double bandCells);

  /// @brief Shifts φ by one constant so that its liquid volume (liquidVolume) is `target` [m³]:
  ///        the band lets a slowly moving surface drift from its particles by up to bandCells, so
  ///        the level set alone would not keep the liquid's volume (a sphere lowered into a tank
  ///        raised its level 32 % short); a uniform shift keeps a flat surface flat. The shift is
  ///        (V − target) / A, A the area of the surface (h² per cell with |φ| < h/2), at most h/2.
  ///        Cells inside a scene solid stay air.
  void matchVolume(double target, const Array3f& sceneSolidNodes);

  /// φ [m], negative in the liquid.
  const Array3f& phi() const { return phi_; }

 private:
  /// φ ≥ the depth inside the scene solids (air).
  void keepSolidsDry(const Array3f& sceneSolidNodes);

  GridGeometry grid_;
  Array3f phi_;
};

/// @brief The liquid volume [m³] φ describes outside the scene solids: as liquidVolume, each of
///        the 4 × 4 × 4 samples of a cell near the surface or a solid counted only outside the
///        solids (`sceneSolidNodes`, no domain walls), so a solid under the surface displaces its
///        own volume.
double liquidVolumeOutsideSolids(const Array3f& phi, const Array3f& sceneSolidNodes,
                                 const GridGeometry& grid);

/// @brief φ for the pressure solve with the cells whose centre lies inside a solid given the
///        mean φ of their neighbours across the horizontal (perpendicular to `up`) faces that are
///        not inside a solid: a flat surface runs on through the solid at its own height, so the
///        cut cells at a contact line see the level the liquid has (a sloped floor, a sphere
///        through the surface: at rest to round-off). A cell with no such neighbour but one
///        outside the solid above (below) it takes that φ − h (+ h): a flat level continued
///        downward (upward). Two more passes do the same from the cells filled before (the
///        corner of two walls off the cell planes). Others keep φ.
/// @param solidNodes  solid signed distance at the nodes [m]
/// @param up          the grid step against gravity (one axis)
/// @param h           cell size [m]
Array3f extendLevelAcrossSolids(const Array3f& phi, const Array3f& solidNodes, const Index3& up,
                                double h);

}  // namespace fluidsound::sim
