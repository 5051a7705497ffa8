// tests/acoustics/modal/voxel_solid_test.cpp — voxel solids and their hexahedral mesh
// (voxel_solid.h): a box is tiled exactly, a sphere's voxels hold its volume, nodes are shared and
// numbered in grid order, and the surface is every node not buried in solid cells.
#include "acoustics/modal/voxel_solid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fluidsound::acoustics {
namespace {

TEST(VoxelSolid, BoxIsTiledExactlyBySortedCells) {
  // Claim: a 0.5 × 0.02 × 0.01 m box at 2.5 mm is 200 × 8 × 4 cells covering [0, size], sorted
  // and unique. Reference: the sizes divided by the cell. Exact.
  const VoxelSolid box = voxelBox({0.5, 0.02, 0.01}, 0.0025);
  EXPECT_EQ(box.cells.size(), 200u * 8u * 4u);
  EXPECT_EQ(box.origin, Eigen::Vector3d::Zero());
  EXPECT_TRUE(std::is_sorted(box.cells.begin(), box.cells.end(), gridIndexLess));
  EXPECT_EQ(std::adjacent_find(box.cells.begin(), box.cells.end()), box.cells.end());
  EXPECT_EQ(box.cells.front(), Eigen::Vector3i(0, 0, 0));
  EXPECT_EQ(box.cells.back(), Eigen::Vector3i(199, 7, 3));
}

TEST(VoxelSolid, BoxRejectsASizeThatIsNotWholeCells) {
  // Claim: a size off a whole number of cells by more than rounding is refused; one off by
  // rounding (0.3/0.1 = 2.9999999999999996) is accepted.
  EXPECT_THROW(voxelBox({0.1, 0.1, 0.0025}, 0.002), std::invalid_argument);
  EXPECT_THROW(voxelBox({0.1, 0.0, 0.1}, 0.01), std::invalid_argument);
  EXPECT_THROW(voxelBox({0.1, 0.1, 0.1}, 0.0), std::invalid_argument);
  EXPECT_EQ(voxelBox({0.3, 0.1, 0.1}, 0.1).cells.size(), 3u);
}

TEST(VoxelSolid, SphereVoxelsHoldItsVolume) {
  // Claim: the cells whose centre is inside a sphere of radius a = 10 h hold its volume 4πa³/3.
  // Reference: closed form. Tolerance: the staircase moves the surface in and out by up to h/2;
  // a whole h/2 shell would be 15 % of the volume at a = 10h, but the steps in and out largely
  // cancel (measured 0.8 %): 2 % allowed.
  const double radius = 0.1, voxelSize = 0.01;
  const VoxelSolid sphere = voxelSolidFromInside(
      [&](const Eigen::Vector3d& x) { return x.norm() < radius; },
      Eigen::Vector3d::Constant(-radius), Eigen::Vector3d::Constant(radius), voxelSize);
  const double volume = static_cast<double>(sphere.cells.size()) * std::pow(voxelSize, 3);
  const double expected = 4.0 / 3.0 * std::numbers::pi * std::pow(radius, 3);
  EXPECT_NEAR(volume, expected, 0.02 * expected);
  EXPECT_TRUE(std::is_sorted(sphere.cells.begin(), sphere.cells.end(), gridIndexLess));
  for (const Eigen::Vector3i& cell : sphere.cells) {
    const Eigen::Vector3d centre =
        sphere.origin + voxelSize * (cell.cast<double>() + Eigen::Vector3d::Constant(0.5));
    EXPECT_LT(centre.norm(), radius);
  }
  EXPECT_THROW(voxelSolidFromInside([](const Eigen::Vector3d&) { return true; },
                                    Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 1), 0.1),
               std::invalid_argument);
}

TEST(HexMesh, NodesAreSharedAndElementsFollowTheLocalOrder) {
  // Claim: a 3 × 2 × 2 box has 4·3·3 = 36 distinct nodes in grid order; element corner
  // dx + 2dy + 4dz sits at the cell's corner + h(dx, dy, dz). Exact.
  const VoxelSolid box = voxelBox({0.03, 0.02, 0.02}, 0.01);
  const HexMesh mesh = hexMesh(box);
  ASSERT_EQ(mesh.gridNodes.size(), 36u);
  ASSERT_EQ(mesh.positions.size(), 36u);
  ASSERT_EQ(mesh.elements.size(), box.cells.size());
  EXPECT_TRUE(std::is_sorted(mesh.gridNodes.begin(), mesh.gridNodes.end(), gridIndexLess));
  EXPECT_EQ(mesh.elementSize, 0.01);
  for (std::size_t e = 0; e < box.cells.size(); ++e)
    for (int a = 0; a < 8; ++a) {
      const Eigen::Vector3i corner =
          box.cells[e] + Eigen::Vector3i(a & 1, (a >> 1) & 1, (a >> 2) & 1);
      const int node = mesh.elements[e][a];
      EXPECT_EQ(mesh.gridNodes[node], corner);
      EXPECT_LT((mesh.positions[node] - 0.01 * corner.cast<double>()).norm(), 1e-15);
    }
  // Cells (0,0,0) and (1,0,0) share their common face's four nodes.
  EXPECT_EQ(mesh.elements[0][1], mesh.elements[4][0]);
  EXPECT_EQ(mesh.elements[0][7], mesh.elements[4][6]);
}

TEST(HexMesh, SurfaceIsEveryNodeNotBuriedInSolidCells) {
  // Claim: for a 4 × 4 × 4 box the surface nodes are all 125 but the 3³ interior ones; for a
  // box with one interior cell removed (a cavity) the cavity's 8 corners join the surface
  // (they are interior nodes of the full box, on faces shared by no two solid cells). Exact.
  VoxelSolid box = voxelBox({0.04, 0.04, 0.04}, 0.01);
  EXPECT_EQ(surfaceNodes(box, hexMesh(box)).size(), 125u - 27u);
  box.cells.erase(std::find(box.cells.begin(), box.cells.end(), Eigen::Vector3i(1, 1, 1)));
  const HexMesh mesh = hexMesh(box);
  const std::vector<int> surface = surfaceNodes(box, mesh);
  EXPECT_EQ(surface.size(), 125u - 27u + 8u);
  EXPECT_TRUE(std::is_sorted(surface.begin(), surface.end()));
}

}  // namespace
}  // namespace fluidsound::acoustics
