// tests/sim/fluid/thin_wall_faces_test.cpp — closing the pressure-solve faces that a mesh wall thinner
// than a cell separates, and leaving the variational weights of walls the grid resolves alone.
#include "sim/fluid/thin_wall_faces.h"

#include <algorithm>
#include <memory>

#include <gtest/gtest.h>

#include "sim/fluid/solid_geometry.h"
#include "support/test_meshes.h"

namespace fluidsound::sim {
namespace {

constexpr double kCell = 0.005;  // [m]
const GridGeometry kGrid{{8, 4, 4}, kCell, {0.0, 0.0, 0.0}};

Solid meshSolid(const TriangleMesh& mesh) {
  Solid s;
  MeshFile file{"wall.obj"};
  file.surface = std::make_shared<const TriangleMesh>(mesh);
  s.shape = file;
  return s;
}

/// Nodal signed distance [m] to the slab lo ≤ x ≤ hi (infinite in y and z): exact.
Array3f slabNodeDistance(double lo, double hi) {
  Array3f d(kGrid.nodeCount());
  for (int k = 0; k <= kGrid.cells[2]; ++k)
    for (int j = 0; j <= kGrid.cells[1]; ++j)
      for (int i = 0; i <= kGrid.cells[0]; ++i) {
        const double x = i * kCell;
        d(i, j, k) = static_cast<float>(std::max(lo - x, x - hi));
      }
  return d;
}

TEST(ThinWallFaces, AWallBetweenTwoNodePlanesClosesTheFacesThroughIt) {
  // Claim: the slab 0.0231 ≤ x ≤ 0.0249 (1.8 mm, between the node planes x = 0.020 and 0.025 and
  // between the cell centres 0.0225 and 0.0275) leaves every nodal distance positive, so the
  // variational weights are all 1; the ray test closes exactly the x-faces at x = 0.025 (i = 5)
  // — 16 of them — and nothing else. Reference: the geometry above.
  const Array3f nodes = slabNodeDistance(0.0231, 0.0249);
  std::array<Array3f, 3> open = faceOpenFractions(nodes, kGrid);
  for (int a = 0; a < 3; ++a)
    for (float w : open[a].values()) ASSERT_EQ(w, 1.0f);
  const Solid wall = meshSolid(test::boxMesh({0.0231f, -1.0f, -1.0f}, {0.0249f, 1.0f, 1.0f}));
  const SolidMeshRays rays(std::span(&wall, 1));
  EXPECT_EQ(closeFacesAcrossThinWalls(open, nodes, rays, kGrid, 0.0), 16u);
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i <= 8; ++i) EXPECT_EQ(open[0](i, j, k), i == 5 ? 0.0f : 1.0f) << i << "," << j << "," << k;
  for (int a = 1; a < 3; ++a)
    for (float w : open[a].values()) EXPECT_EQ(w, 1.0f);
}

TEST(ThinWallFaces, ASolidTheGridResolvesKeepsItsVariationalWeights) {
  // Claim: for a thick block (x ≥ 0.0231, beyond the grid) the nodal distance is negative from
  // x = 0.025 on, the faces cut by it are partly open, and the ray test changes none of the
  // weights (the centres beyond the surface read inside). Reference: the weights before.
  const Array3f nodes = slabNodeDistance(0.0231, 1.0);
  std::array<Array3f, 3> open = faceOpenFractions(nodes, kGrid);
  const std::array<Array3f, 3> before = open;
  const Solid block = meshSolid(test::boxMesh({0.0231f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}));
  const SolidMeshRays rays(std::span(&block, 1));
  EXPECT_EQ(closeFacesAcrossThinWalls(open, nodes, rays, kGrid, 0.0), 0u);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(open[a].values(), before[a].values()) << "axis " << a;
  // The y-faces of the cut cells are partly open: the test would see a change.
  EXPECT_GT(before[1](4, 1, 1), 0.0f);
  EXPECT_LT(before[1](4, 1, 1), 1.0f);
}

}  // namespace
}  // namespace fluidsound::sim
