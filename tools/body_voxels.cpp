// tools/body_voxels.cpp — see body_voxels.h.
#include "tools/body_voxels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "sim/fluid/mesh_distance.h"

namespace fluidsound::tools {

acoustics::VoxelSolid voxeliseBody(const sim::TriangleMesh& mesh, double scale, int resolution) {
  if (!(scale > 0.0) || !std::isfinite(scale) || resolution < 2)
    throw std::invalid_argument("voxeliseBody: scale must be > 0 and resolution >= 2");
  std::array<double, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<double>::max());
  hi.fill(-std::numeric_limits<double>::max());
  for (const auto& v : mesh.vertices)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], scale * v[a]), hi[a] = std::max(hi[a], scale * v[a]);
  const double longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  acoustics::VoxelSolid solid;
  solid.voxelSize = longest / resolution;
  solid.origin = {lo[0], lo[1], lo[2]};
  // The distance grid's nodes are the voxels' centres: origin + h/2 + (i, j, k)·h.
  sim::GridGeometry centres;
  centres.cellSize = solid.voxelSize;
  for (int a = 0; a < 3; ++a) {
    const int cells = std::max(1, static_cast<int>(std::ceil((hi[a] - lo[a]) / solid.voxelSize - 1e-9)));
    centres.cells[a] = cells - 1;  // nodes = cells
    centres.origin[a] = lo[a] + 0.5 * solid.voxelSize;
  }
  const sim::Array3f distance = sim::meshNodeDistance(mesh, {scale, {}}, centres);
  const sim::Index3 n = centres.nodeCount();
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k)
        if (distance(i, j, k) < 0.0f) solid.cells.emplace_back(i, j, k);
  std::sort(solid.cells.begin(), solid.cells.end(), acoustics::gridIndexLess);
  return solid;
}

std::string voxelResolutionProblem(const acoustics::VoxelSolid& solid, int resolution) {
  if (!solid.cells.empty()) return {};
  std::ostringstream text;
  text << "no voxel inside it: the voxels' centres, " << solid.voxelSize * 1e3 << " mm apart (--resolution "
       << resolution << "), all miss the body; raise --resolution until its thinnest part holds one";
  return text.str();
}

}  // namespace fluidsound::tools
