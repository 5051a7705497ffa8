// sim/fluid/triangle_mesh.h — a triangle mesh as a plain value type: what io/mesh_file.h reads from an
// OBJ or PLY file (a liquid region or a solid of the scene) and what the geometry code consumes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace fluidsound::sim {

/// @brief An indexed triangle mesh, as written in its file (no scale, rotation or translation
///        applied; scene meshes are in metres before `scale`).
/// @note  Valid meshes (io::readMeshFile) have at least one triangle, finite vertices and every
///        index < vertices.size(). Vertices no triangle uses may be present. A closed mesh
///        (meshClosedness, io/mesh_closedness.h) is oriented outward or inward alike: the
///        distance code (sim/fluid/mesh_distance.h) does not depend on the orientation.
struct TriangleMesh {
  std::vector<std::array<float, 3>> vertices;           ///< positions [file units, m for scenes]
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< 0-based indices into vertices
  bool operator==(const TriangleMesh&) const = default;
};

}  // namespace fluidsound::sim
