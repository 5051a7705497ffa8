// sim/fluid/solid_boundary.cpp — see solid_boundary.h.
#include "sim/fluid/solid_boundary.h"

#include "sim/fluid/solid_geometry.h"
#include "sim/fluid/thin_wall_faces.h"

namespace fluidsound::sim {
namespace {
/// The domain with every face open: its solid distance is that of the scene's solids alone.
Domain withoutWalls(Domain domain) {
  domain.open.fill(true);
  return domain;
}
}  // namespace

SolidBoundary solidBoundaryAt(const GridGeometry& grid, const Domain& domain,
                              std::span<const Solid> solids, const SolidMeshRays& meshes,
                              double time, std::span<const MeshNodeDistance> solidMeshes) {
  SolidBoundary boundary;
  boundary.grid = grid;
  boundary.domain = domain;
  boundary.meshes = &meshes;
  boundary.nodeDistance = solidNodeDistance(grid, domain, solids, time, solidMeshes);
  boundary.sceneNodeDistance = solidNodeDistance(grid, withoutWalls(domain), solids, time, solidMeshes);
  boundary.faceOpen = faceOpenFractions(boundary.nodeDistance, grid);
  closeFacesAcrossThinWalls(boundary.faceOpen, boundary.nodeDistance, meshes, grid, time);
  boundary.faceVelocity = solidFaceVelocity(grid, domain, solids, time, solidMeshes);
  return boundary;
}

void constrainToSolids(MacVelocity& velocity, const SolidBoundary& solids) {
  for (int a = 0; a < 3; ++a) {
    auto& u = velocity[a].values();
    const auto& open = solids.faceOpen[a].values();
    const auto& solid = solids.faceVelocity[a].values();
    for (std::size_t f = 0; f < u.size(); ++f)
      if (open[f] <= 0.0f) u[f] = solid[f];
  }
}

}  // namespace fluidsound::sim
