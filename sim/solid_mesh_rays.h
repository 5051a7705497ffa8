// sim/solid_mesh_rays.h — ray queries against the scene's mesh solids (Embree), so that liquid
// never crosses a solid wall thinner than a grid cell: the nodal signed distance the pressure
// solve uses cannot see a 2 mm glass wall in 5 mm cells (io/mesh_distance.h, "Thin features"),
// but a ray along each particle's move finds it whatever its thickness (docs/solver.md, "Thin
// walls").
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "sim/grid.h"
#include "sim/scene.h"

namespace fluidsound::sim {

/// Where a move meets a mesh surface first.
struct WallStop {
  Vec3 position{};      ///< where the mover stops [m]: `offset` short of the surface on its side
  Vec3 normal{};        ///< unit surface normal, facing the side the mover came from
  Vec3 wallVelocity{};  ///< velocity of the solid that was hit (its path) [m/s]
};

/// @brief The triangles of every mesh solid of a scene (MeshFile::surface, placed by scale and
///        translation) in one Embree BVH per solid, queried with single rays in robust
///        (watertight) mode so that a ray through an edge or a vertex of a closed mesh is never
///        missed. A kinematic solid (Solid::path, translation only) is queried in its own frame:
///        a particle moving from x₀ at t₀ to x₁ at t₁ is the segment x₀ − d(t₀) → x₁ − d(t₁)
///        there (d the path translation), which is exact for the swept solid.
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

  /// @brief The first mesh surface crossed by a point moving in a straight line from `from` at
  ///        time `timeFrom` to `to` at `timeTo` (relative to each solid's own motion), or nothing.
  /// @param offset  [m] > 0: the returned position lies this far from the surface on the side of
  ///                `from` (along the surface normal), and at most at the hit along the move;
  ///                large against float rounding of positions (≈ 1e-8 m), small against a cell
  std::optional<WallStop> firstCrossing(const Vec3& from, const Vec3& to, double timeFrom, double timeTo,
                                        double offset) const;

  /// @brief Whether the segment a → b, with the solids placed at `time`, crosses a mesh surface.
  bool crosses(const Vec3& a, const Vec3& b, double time) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fluidsound::sim
