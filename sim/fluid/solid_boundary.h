// sim/fluid/solid_boundary.h — the solids as every stage of the liquid solver reads them: the
// domain box, the solid distance at the nodes (with and without the domain walls), the open
// fraction and solid velocity of each MAC face, and the mesh solids' ray queries. Built once per
// substep (once per run when no solid moves) and passed whole.
#pragma once

#include <array>
#include <span>

#include "sim/fluid/array3.h"
#include "sim/fluid/fluid_scene.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/scene_mesh_distances.h"
#include "sim/fluid/solid_mesh_rays.h"

namespace fluidsound::sim {

/// The solid boundary of the liquid at one time, on the solver grid.
struct SolidBoundary {
  /// The solver grid the fields below are sampled on.
  GridGeometry grid;
  /// The box: closed faces are walls, liquid leaving through an open one is deleted.
  Domain domain;
  /// Solid signed distance at the nodes, domain walls included [m].
  Array3f nodeDistance;
  /// The same for the scene's solids alone (no domain walls) [m].
  Array3f sceneNodeDistance;
  /// Open fraction of each MAC face [0, 1], the faces across thin mesh walls closed.
  std::array<Array3f, 3> faceOpen;
  /// Solid velocity at each MAC face, its normal component [m/s].
  std::array<Array3f, 3> faceVelocity;
  /// Ray queries against the mesh solids (never null; may be empty).
  const SolidMeshRays* meshes = nullptr;
};

/// @brief Faces wholly inside solids (open fraction ≤ 0) take the solid's velocity, after
///        extrapolation filled them with liquid velocities: no particle is carried into a wall, and
///        a test probing into one reads the wall's velocity (Batty's Fluid3D `constrain_velocity`,
///        here for the whole velocity of closed faces). The solver and a cache's import use it.
void constrainToSolids(MacVelocity& velocity, const SolidBoundary& solids);

/// The times [s] at which the mesh solids are placed for a particle move: where it starts and
/// where it ends (from = to for an instantaneous move such as a position correction).
struct SolidTimes {
  double from = 0.0;
  double to = 0.0;
};

/// @brief The solid boundary at `time` [s]: solidNodeDistance with and without the domain walls,
///        faceOpenFractions of the former with the faces across thin mesh walls closed
///        (closeFacesAcrossThinWalls), solidFaceVelocity.
/// @param meshes       SolidMeshRays of `solids`; must outlive the result (it keeps a pointer)
/// @param solidMeshes  the mesh solids' node distances on `grid` (SceneMeshDistances::solids);
///                     may be empty when no solid is a mesh
/// @throws std::invalid_argument for a MeshFile solid whose distance solidMeshes does not hold
SolidBoundary solidBoundaryAt(const GridGeometry& grid, const Domain& domain,
                              std::span<const Solid> solids, const SolidMeshRays& meshes,
                              double time, std::span<const MeshNodeDistance> solidMeshes = {});

}  // namespace fluidsound::sim
