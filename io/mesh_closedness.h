// io/mesh_closedness.h — scene input check: whether a triangle mesh bounds a volume (watertight,
// manifold along its edges, consistently oriented), and if not, what is wrong and where.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "sim/fluid/triangle_mesh.h"

namespace fluidsound::io {

/// An edge as its two vertex indices, smaller first.
using MeshEdge = std::array<std::uint32_t, 2>;

/// @brief The edge diagnosis of a triangle mesh. Vertices at exactly the same position count as
///        one vertex (the smallest index among them), so a file that repeats a vertex for every
///        face it touches (as meshes converted from STL do) is closed when its surface is.
struct MeshClosedness {
  std::size_t edges = 0;             ///< distinct edges of non-degenerate triangles
  std::size_t boundaryEdges = 0;     ///< edges of exactly one triangle: the rims of holes
  std::size_t nonManifoldEdges = 0;  ///< edges of three or more triangles
  /// Edges of exactly two triangles that both run along it in the same direction: one of the two
  /// triangles is flipped relative to the other.
  std::size_t misorientedEdges = 0;
  /// Triangles with two corners at one position. They have no area and are left out of the edge
  /// counts above (they neither open nor close the surface).
  std::size_t degenerateTriangles = 0;
  /// The smallest edge (lexicographic in welded vertex indices) of each kind, for messages;
  /// {0, 0} when there is none.
  MeshEdge firstBoundaryEdge{}, firstNonManifoldEdge{}, firstMisorientedEdge{};
  /// Σ over all triangles of v0 · (v1 × v2) / 6 [file units³]: the enclosed volume of a closed
  /// mesh, positive when its triangles turn counter-clockwise seen from outside (normals out),
  /// negative when the whole mesh is oriented inward; meaningless for an open mesh.
  double signedVolume = 0.0;

  /// Closed: every edge belongs to exactly two triangles that run along it in opposite
  /// directions (watertight, edge-manifold, consistently oriented).
  /// @note Two closed pieces that touch at a single vertex pass this edge test.
  bool closed() const {
    return boundaryEdges == 0 && nonManifoldEdges == 0 && misorientedEdges == 0;
  }
  bool operator==(const MeshClosedness&) const = default;
};

/// @brief Diagnoses the edges of `mesh` (see MeshClosedness). O(n log n) in the triangle count.
/// @param mesh  any triangle mesh with finite vertices and indices < vertices.size()
/// @return the counts, the first edge of each kind and the signed volume
MeshClosedness meshClosedness(const sim::TriangleMesh& mesh);

}  // namespace fluidsound::io
