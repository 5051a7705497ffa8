// tests/io/mesh_closedness_test.cpp — the edge diagnosis of triangle meshes: closed, holed,
// non-manifold, misoriented and degenerate cases, vertex welding, and the enclosed volume.
#include "io/mesh_closedness.h"

#include <gtest/gtest.h>

#include "support/test_meshes.h"

namespace fluidsound::io {

using sim::TriangleMesh;
namespace {

TEST(MeshClosedness, BoxIsClosedAndEnclosesItsVolume) {
  // Claim: the box [0,2]×[0,3]×[0,4] is closed with 18 edges (12 + 6 face diagonals) and its
  // signed volume is +24 (outward) or −24 with every triangle flipped. Reference: 2·3·4.
  // Tolerance: exact (products of small integers in double).
  TriangleMesh box = test::boxMesh({0, 0, 0}, {2, 3, 4});
  MeshClosedness c = meshClosedness(box);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.edges, 18u);
  EXPECT_EQ(c.degenerateTriangles, 0u);
  EXPECT_DOUBLE_EQ(c.signedVolume, 24.0);
  for (auto& t : box.triangles) std::swap(t[1], t[2]);
  c = meshClosedness(box);
  EXPECT_TRUE(c.closed());
  EXPECT_DOUBLE_EQ(c.signedVolume, -24.0);
}

TEST(MeshClosedness, RepeatedVerticesAtOnePositionAreWelded) {
  // Claim: a box written with its own 3 vertices per triangle (36 vertices, as STL-derived files
  // are) is as closed as the indexed one, and the first problem edge is named by the smallest
  // index at each position.
  const TriangleMesh indexed = test::boxMesh({0, 0, 0}, {1, 1, 1});
  TriangleMesh soup;
  for (const auto& t : indexed.triangles) {
    const auto base = static_cast<std::uint32_t>(soup.vertices.size());
    for (int c = 0; c < 3; ++c) soup.vertices.push_back(indexed.vertices[t[c]]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  EXPECT_TRUE(meshClosedness(soup).closed());
  EXPECT_EQ(meshClosedness(soup).edges, 18u);
  soup.triangles.pop_back();  // the second triangle of the +z face
  const MeshClosedness open = meshClosedness(soup);
  EXPECT_EQ(open.boundaryEdges, 3u);
  // The lost triangle's corners (0,0,1), (1,1,1), (0,1,1) first occur as soup vertices 1, 8, 2.
  EXPECT_EQ(open.firstBoundaryEdge, (MeshEdge{1, 2}));
  EXPECT_FALSE(open.closed());
}

TEST(MeshClosedness, FinOnAnEdgeIsNonManifold) {
  // Claim: a third triangle hung on a box edge makes that edge non-manifold and leaves the
  // fin's two other edges as boundary edges.
  TriangleMesh box = test::boxMesh({0, 0, 0}, {1, 1, 1});
  box.vertices.push_back({0.5f, -1.0f, 0.0f});
  box.triangles.push_back({0, 1, 8});  // on the edge (0, 1)
  const MeshClosedness c = meshClosedness(box);
  EXPECT_EQ(c.nonManifoldEdges, 1u);
  EXPECT_EQ(c.firstNonManifoldEdge, (MeshEdge{0, 1}));
  EXPECT_EQ(c.boundaryEdges, 2u);
  EXPECT_EQ(c.firstBoundaryEdge, (MeshEdge{0, 8}));
  EXPECT_FALSE(c.closed());
}

TEST(MeshClosedness, DegenerateTrianglesAreCountedButDoNotOpenTheSurface) {
  // Claim: a triangle with a repeated corner (by index, or by position) has no area and is left
  // out of the edge test: the box stays closed.
  TriangleMesh box = test::boxMesh({0, 0, 0}, {1, 1, 1});
  box.triangles.push_back({0, 0, 1});
  box.vertices.push_back({1, 1, 1});  // a copy of vertex 7
  box.triangles.push_back({7, 8, 3});
  const MeshClosedness c = meshClosedness(box);
  EXPECT_EQ(c.degenerateTriangles, 2u);
  EXPECT_TRUE(c.closed());
}

TEST(MeshClosedness, IcosphereIsClosed) {
  const TriangleMesh sphere = test::icosphere(2);
  const MeshClosedness c = meshClosedness(sphere);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.edges, 480u);  // Euler: E = 3F/2 = 3·320/2
  EXPECT_GT(c.signedVolume, 0.0);
}

}  // namespace
}  // namespace fluidsound::io
