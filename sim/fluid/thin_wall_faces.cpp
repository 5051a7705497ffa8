// sim/fluid/thin_wall_faces.cpp — see thin_wall_faces.h.
#include "sim/fluid/thin_wall_faces.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "sim/fluid/solid_geometry.h"

namespace fluidsound::sim {

std::size_t closeFacesAcrossThinWalls(std::array<Array3f, 3>& faceOpen, const Array3f& solidNodeDistance,
                                      const SolidMeshRays& meshes, const GridGeometry& grid, double time) {
  if (meshes.empty()) return 0;
  const auto centreDistance = [&](int i, int j, int k) { return cellCentreSolidDistance(solidNodeDistance, i, j, k); };
  std::size_t closed = 0;
  for (int a = 0; a < 3; ++a) {
    Array3f& open = faceOpen[a];
    const Index3 n = open.size();
    // Faces on the grid's boundary have one cell only: the domain walls close or open them.
    closed += tbb::parallel_reduce(
        tbb::blocked_range<int>(0, n[2]), std::size_t{0},
        [&](const tbb::blocked_range<int>& slabs, std::size_t count) {
          for (int k = slabs.begin(); k < slabs.end(); ++k)
            for (int j = 0; j < n[1]; ++j)
              for (int i = 0; i < n[0]; ++i) {
                if (open(i, j, k) <= 0.0f) continue;
                Index3 plus{i, j, k}, minus{i, j, k};
                --minus[a];
                if (minus[a] < 0 || plus[a] >= grid.cells[a]) continue;
                if (centreDistance(plus[0], plus[1], plus[2]) <= 0.0f ||
                    centreDistance(minus[0], minus[1], minus[2]) <= 0.0f)
                  continue;
                if (!meshes.crosses(grid.cellCentre(minus[0], minus[1], minus[2]),
                                    grid.cellCentre(plus[0], plus[1], plus[2]), time))
                  continue;
                open(i, j, k) = 0.0f;  // each face is written by one task only
                ++count;
              }
          return count;
        },
        [](std::size_t x, std::size_t y) { return x + y; });
  }
  return closed;
}

}  // namespace fluidsound::sim
