// tests/sim/fluid/solid_boundary_test.cpp — the solid boundary the liquid solver builds once per
// substep: the domain walls in one distance and not in the other, the fields as the single
// functions give them, a moving solid placed at the boundary's time.
#include "sim/fluid/solid_boundary.h"

#include <gtest/gtest.h>

#include "sim/fluid/solid_geometry.h"
#include "support/cube_grid.h"

namespace fluidsound::sim {
namespace {

constexpr double kCell = 0.01;  // h [m]
constexpr int kSide = 8;        // cells per side of the closed box
constexpr double kSpeed = 0.5;  // [m/s] along +x, the moving block's path

/// The closed 8³ box of 1 cm cells (its top open) with a 2 × 2 × 2 cm block in the middle that
/// moves along +x at kSpeed from t = 0.
struct BoxWithMovingBlock {
  GridGeometry grid = test::cubeGrid(kSide, kCell);
  Domain domain;
  std::vector<Solid> solids;
  SolidMeshRays noMeshes;

  BoxWithMovingBlock() {
    domain.max = {kSide * kCell, kSide * kCell, kSide * kCell};
    domain.cell = kCell;
    domain.open = {false, false, false, true, false, false};  // +y open
    Solid block;
    block.shape = Box{{0.03, 0.03, 0.03}, {0.05, 0.05, 0.05}};
    block.path = {PathKey{0.0, {0.0, 0.0, 0.0}}, PathKey{1.0, {kSpeed, 0.0, 0.0}}};
    solids.push_back(block);
  }
};

TEST(SolidBoundary, DomainWallsAreInTheNodeDistanceButNotInTheSceneDistance) {
  // Claim: at a node on a closed wall (x = 0) the distance with walls is ≤ 0 while the scene's
  // own distance is that to the block (> 0); inside the block both are < 0; at the open top the
  // two agree (no wall there). Reference: the geometry of the box and the block.
  const BoxWithMovingBlock scene;
  const SolidBoundary b =
      solidBoundaryAt(scene.grid, scene.domain, scene.solids, scene.noMeshes, 0.0);
  EXPECT_LE(b.nodeDistance(0, 4, 4), 0.0f);
  EXPECT_GT(b.sceneNodeDistance(0, 4, 4), 0.0f);
  EXPECT_LT(b.nodeDistance(4, 4, 4), 0.0f);
  EXPECT_LT(b.sceneNodeDistance(4, 4, 4), 0.0f);
  EXPECT_EQ(b.nodeDistance(4, kSide, 4), b.sceneNodeDistance(4, kSide, 4));
  EXPECT_EQ(b.domain, scene.domain);
  EXPECT_EQ(b.grid.cells, scene.grid.cells);
  EXPECT_EQ(b.meshes, &scene.noMeshes);
}

TEST(SolidBoundary, HoldsWhatTheSingleFunctionsGiveAtItsTime) {
  // Claim: the boundary at t = 0.02 s (the block moved 1 cm) holds bit for bit the node
  // distance, face fractions and face velocities that solidNodeDistance, faceOpenFractions and
  // solidFaceVelocity give at that time (no mesh solid: no face closed by rays), and the faces
  // the block covers move at the path's speed. Reference: those functions; the path's slope.
  const BoxWithMovingBlock scene;
  constexpr double kTime = 0.02;
  const SolidBoundary b =
      solidBoundaryAt(scene.grid, scene.domain, scene.solids, scene.noMeshes, kTime);
  const Array3f nodes = solidNodeDistance(scene.grid, scene.domain, scene.solids, kTime);
  EXPECT_EQ(b.nodeDistance.values(), nodes.values());
  const std::array<Array3f, 3> open = faceOpenFractions(nodes, scene.grid);
  const std::array<Array3f, 3> velocity =
      solidFaceVelocity(scene.grid, scene.domain, scene.solids, kTime);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(b.faceOpen[a].values(), open[a].values()) << "axis " << a;
    EXPECT_EQ(b.faceVelocity[a].values(), velocity[a].values()) << "axis " << a;
  }
  // The x-face at x = 0.05 m lies inside the block moved to 0.04–0.06 m.
  EXPECT_EQ(b.faceOpen[0](5, 4, 4), 0.0f);
  EXPECT_FLOAT_EQ(b.faceVelocity[0](5, 4, 4), static_cast<float>(kSpeed));
  // The block at t = 0 covered x = 0.03 m; at 0.02 s that face is open again.
  const SolidBoundary start =
      solidBoundaryAt(scene.grid, scene.domain, scene.solids, scene.noMeshes, 0.0);
  EXPECT_EQ(start.faceOpen[0](3, 4, 4), 0.0f);
  EXPECT_EQ(b.faceOpen[0](3, 4, 4), 1.0f);
}

}  // namespace
}  // namespace fluidsound::sim
