// io/mesh_closedness.cpp — see mesh_closedness.h.
#include "io/mesh_closedness.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace fluidsound::io {
namespace {

/// For every vertex, the smallest index of a vertex at exactly the same position (-0 and +0 are
/// the same position). Sorting keeps the result independent of hashing and thread count.
std::vector<std::uint32_t> weldedVertexIndices(const sim::TriangleMesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), std::uint32_t{0});
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (mesh.vertices[a] != mesh.vertices[b]) return mesh.vertices[a] < mesh.vertices[b];
    return a < b;
  });
  std::vector<std::uint32_t> welded(n);
  for (std::size_t i = 0; i < n;) {
    std::size_t end = i + 1;
    while (end < n && mesh.vertices[order[end]] == mesh.vertices[order[i]]) ++end;
    for (std::size_t k = i; k < end; ++k) welded[order[k]] = order[i];  // order[i]: smallest index
    i = end;
  }
  return welded;
}

/// One triangle's use of an edge: the edge (smaller index first) and whether the triangle runs
/// from the smaller to the larger index.
struct EdgeUse {
  MeshEdge edge;
  bool forward;
};

}  // namespace

MeshClosedness meshClosedness(const sim::TriangleMesh& mesh) {
  MeshClosedness result;
  const std::vector<std::uint32_t> welded = weldedVertexIndices(mesh);

  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.triangles.size());
  for (const auto& triangle : mesh.triangles) {
    const std::array<std::uint32_t, 3> c{welded[triangle[0]], welded[triangle[1]],
                                         welded[triangle[2]]};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) {
      ++result.degenerateTriangles;
    } else {
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t from = c[e], to = c[(e + 1) % 3];
        uses.push_back({MeshEdge{std::min(from, to), std::max(from, to)}, from < to});
      }
    }
    // Signed volume of the tetrahedron (origin, v0, v1, v2), in double.
    const auto& a = mesh.vertices[triangle[0]];
    const auto& b = mesh.vertices[triangle[1]];
    const auto& d = mesh.vertices[triangle[2]];
    const double cross[3] = {double(b[1]) * d[2] - double(b[2]) * d[1],
                             double(b[2]) * d[0] - double(b[0]) * d[2],
                             double(b[0]) * d[1] - double(b[1]) * d[0]};
    result.signedVolume += (a[0] * cross[0] + a[1] * cross[1] + a[2] * cross[2]) / 6.0;
  }

  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.edge != y.edge ? x.edge < y.edge : x.forward < y.forward;
  });
  // Edges are visited in increasing order, so the first one of each kind is the smallest.
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t end = i + 1;
    while (end < uses.size() && uses[end].edge == uses[i].edge) ++end;
    const std::size_t count = end - i;
    ++result.edges;
    if (count == 1) {
      if (result.boundaryEdges++ == 0) result.firstBoundaryEdge = uses[i].edge;
    } else if (count > 2) {
      if (result.nonManifoldEdges++ == 0) result.firstNonManifoldEdge = uses[i].edge;
    } else if (uses[i].forward == uses[i + 1].forward) {
      if (result.misorientedEdges++ == 0) result.firstMisorientedEdge = uses[i].edge;
    }
    i = end;
  }
  return result;
}

}  // namespace fluidsound::io
