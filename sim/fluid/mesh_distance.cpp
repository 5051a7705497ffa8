// sim/fluid/mesh_distance.cpp — see mesh_distance.h. Its own file: instantiating OpenVDB's
// MeshToVolume takes about 20 s to compile (docs/toolchain facts).
#include "sim/fluid/mesh_distance.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fluidsound::sim {
namespace {

/// The MeshDataAdapter interface of openvdb::tools::meshToVolume: the mesh's triangles with
/// their corners placed in the scene and expressed in grid index space (node (i, j, k) at
/// (i, j, k)), computed in double from the float file coordinates.
class PlacedTriangles {
 public:
  PlacedTriangles(const TriangleMesh& mesh, const MeshPlacement& placement,
                  const GridGeometry& grid)
      : mesh_(mesh), placement_(placement), grid_(grid) {}

  std::size_t polygonCount() const { return mesh_.triangles.size(); }
  std::size_t pointCount() const { return mesh_.vertices.size(); }
  std::size_t vertexCount(std::size_t) const { return 3; }
  void getIndexSpacePoint(std::size_t n, std::size_t v, openvdb::Vec3d& pos) const {
    const auto& p = mesh_.vertices[mesh_.triangles[n][v]];
    for (int a = 0; a < 3; ++a) {
      const double world = placement_.scale * p[a] + placement_.translate[a];
      pos[a] = (world - grid_.origin[a]) / grid_.cellSize;
    }
  }

 private:
  const TriangleMesh& mesh_;
  const MeshPlacement& placement_;
  const GridGeometry& grid_;
};

/// OpenVDB grows its band by whole voxels from the voxels the triangles touch, so a node just
/// inside the band's edge (a diagonal neighbour at 2.96 h of a 3 h band) can be left at the
/// background value; computing one cell more than is kept makes every kept value exact.
constexpr int kExtraBandCells = 1;

}  // namespace

namespace {

/// The band of `mesh` sampled at the grid's nodes by meshToVolume with `flags`, clamped to
/// [lowest, halfWidthCells·h]; see meshNodeDistance.
Array3f sampleMeshVolume(const TriangleMesh& mesh, const MeshPlacement& placement,
                         const GridGeometry& grid, const MeshDistanceSettings& settings, int flags,
                         bool isSigned) {
  if (!(placement.scale > 0.0) || !std::isfinite(placement.scale))
    throw std::invalid_argument("meshNodeDistance: scale must be finite and > 0, is " +
                                std::to_string(placement.scale));
  if (settings.halfWidthCells < 2)
    throw std::invalid_argument("meshNodeDistance: halfWidthCells must be >= 2, is " +
                                std::to_string(settings.halfWidthCells));

  const double h = grid.cellSize;
  const float band = static_cast<float>(settings.halfWidthCells * h);
  const float lowest = isSigned ? -band : 0.0f;
  Array3f distance(grid.nodeCount(), band);
  if (mesh.triangles.empty()) return distance;

  // Voxel (i, j, k) is centred on node (i, j, k): index → world is origin + index·h.
  const auto transform = openvdb::math::Transform::createLinearTransform(h);
  transform->postTranslate(openvdb::Vec3d(grid.origin[0], grid.origin[1], grid.origin[2]));
  const auto halfWidth = static_cast<float>(settings.halfWidthCells + kExtraBandCells);
  const openvdb::FloatGrid::Ptr field = openvdb::tools::meshToVolume<openvdb::FloatGrid>(
      PlacedTriangles(mesh, placement, grid), *transform, halfWidth, halfWidth, flags);

  // Inactive voxels hold ±background = ±halfWidth·h already; the clamp also bounds the few
  // band voxels OpenVDB leaves just past the band's edge.
  const Index3 n = grid.nodeCount();
  tbb::parallel_for(tbb::blocked_range<int>(0, n[2]), [&](const tbb::blocked_range<int>& r) {
    auto accessor = field->getConstAccessor();  // one per block: accessors cache, not thread-safe
    for (int k = r.begin(); k < r.end(); ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i)
          distance(i, j, k) = std::clamp(accessor.getValue(openvdb::Coord(i, j, k)), lowest, band);
  });
  return distance;
}

}  // namespace

Array3f meshNodeDistance(const TriangleMesh& mesh, const MeshPlacement& placement,
                         const GridGeometry& grid, const MeshDistanceSettings& settings) {
  return sampleMeshVolume(mesh, placement, grid, settings, openvdb::tools::DISABLE_RENORMALIZATION,
                          true);
}

Array3f meshNodeUnsignedDistance(const TriangleMesh& mesh, const MeshPlacement& placement,
                                 const GridGeometry& grid, const MeshDistanceSettings& settings) {
  return sampleMeshVolume(
      mesh, placement, grid, settings,
      openvdb::tools::UNSIGNED_DISTANCE_FIELD | openvdb::tools::DISABLE_RENORMALIZATION, false);
}

}  // namespace fluidsound::sim
