// tests/support/body_test_meshes.h — the shared test meshes (tests/support/test_meshes.h) in
// the bodies tests' terms: a box between two points and an icosphere of a radius about a centre.
#pragma once

#include "sim/core/vec3.h"
#include "sim/fluid/triangle_mesh.h"
#include "support/test_meshes.h"

namespace fluidsound::sim::test {

/// The box [lo, hi] (12 triangles, counter-clockwise seen from outside).
inline TriangleMesh boxMesh(const Vec3& lo, const Vec3& hi) {
  return fluidsound::test::boxMesh({float(lo[0]), float(lo[1]), float(lo[2])}, {float(hi[0]), float(hi[1]), float(hi[2])});
}

/// A sphere of `radius` about `centre`: the icosahedron split in four `level` times.
inline TriangleMesh icosphereMesh(double radius, int level, const Vec3& centre = {0.0, 0.0, 0.0}) {
  TriangleMesh mesh = fluidsound::test::icosphere(level);
  for (auto& v : mesh.vertices)
    for (int a = 0; a < 3; ++a) v[a] = static_cast<float>(centre[a] + radius * v[a]);
  return mesh;
}

}  // namespace fluidsound::sim::test
