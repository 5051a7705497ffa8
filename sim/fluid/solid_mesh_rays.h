// sim/fluid/solid_mesh_rays.h — ray queries against the scene's mesh solids (Embree), so that
// liquid never crosses a solid wall thinner than a grid cell: the nodal signed distance the
// pressure solve uses cannot see a 2 mm glass wall in 5 mm cells (sim/fluid/mesh_distance.h, "Thin
// features"), but a ray along each particle's move finds it whatever its thickness (docs/solver.md,
// "Thin walls").
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "sim/fluid/grid.h"
#include "sim/fluid/fluid_scene.h"

namespace fluidsound::sim {

/// Where a move meets a mesh surface first.
struct WallStop {
  Vec3 position{};      ///< where the mover stops [m]: `offset` outside the surface, along `normal`
  Vec3 normal{};        ///< unit normal of the surface met, out of the solid
  Vec3 wallVelocity{};  ///< velocity of the solid that was hit (its path) [m/s]
};

/// @brief The triangles of every mesh solid of a scene (MeshFile::surface, placed by scale and
///        translation) in one Embree BVH per solid, queried with single rays in robust
///        (watertight) mode so that a ray through an edge or a vertex of a closed mesh is never
///        missed. A kinematic solid (Solid::path, translation only) is queried in its own frame:
///        a particle moving from x₀ at t₀ to x₁ at t₁ is the segment x₀ − d(t₀) → x₁ − d(t₁)
///        there (d the path translation), which is exact for the swept solid. A closed mesh's
///        triangles give the outward direction (turned round for a mesh oriented inward), so a
///        mover is always returned to the outside of a solid, whichever side its ray began.
///        Const queries are safe from many threads at once (Embree: rtcIntersect1 on a committed
///        scene); the results do not depend on the thread count.
class SolidMeshRays {
 public:
  /// @param solids  the scene's solids; those whose shape is a MeshFile with a loaded `surface`
  ///                take part, the others (boxes, spheres: resolved by the grid) are ignored
  /// @throws std::runtime_error when Embree cannot be initialised
  explicit SolidMeshRays(std::span<const Solid> solids);
  SolidMeshRays();  ///< no solids: every query misses
  ~SolidMeshRays();
  SolidMeshRays(SolidMeshRays&&) noexcept;
  SolidMeshRays& operator=(SolidMeshRays&&) noexcept;

  /// True when no mesh solid takes part (queries then always miss, at no cost).
  bool empty() const;
  /// Appends keys (later than its last) to the path of the scene's solid `sceneIndex`, if it is
  /// a mesh solid here (FluidSolver::extendSolidPath).
  void extendPath(std::size_t sceneIndex, std::span<const PathKey> keys);

  /// @brief The first mesh surface crossed by a point moving in a straight line from `from` at
  ///        time `timeFrom` to `to` at `timeTo` (relative to each solid's own motion), or nothing.
  ///        The move is tested from ½·offset behind `from` to `offset` beyond `to`, so that a
  ///        mover never comes to rest within `offset` of a wall ahead of it, and one that float
  ///        rounding left on or a hair inside a surface is put back on its side. A point that
  ///        does not move is tested only against moving solids.
  ///        Only crossings into a solid count; crossings out of one are passed through.
  /// @param offset  [m] > 0: the returned position lies this far outside the surface (along its
  ///                outward normal); large against float rounding of positions (≈ 1e-8 m),
  ///                small against a cell
  std::optional<WallStop> firstCrossing(const Vec3& from, const Vec3& to, double timeFrom, double timeTo,
                                        double offset) const;

  /// @brief Whether the segment a → b, with the solids placed at `time`, crosses a mesh surface.
  bool crosses(const Vec3& a, const Vec3& b, double time) const;

  /// @brief Whether a mesh surface (solids placed at `time`) crosses one of the 12 edges of the
  ///        axis-aligned box [lo, hi]: true for every wall that cuts through the box, however
  ///        thin (each of its faces separates the box's corners, or one edge enters and leaves
  ///        it); a closed piece of mesh wholly inside the box is not seen.
  bool cutsBox(const Vec3& lo, const Vec3& hi, double time) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fluidsound::sim
