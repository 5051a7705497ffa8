// tests/support/test_meshes.h — small triangle meshes made in the tests (a box, an icosphere) and
// writers for OBJ and PLY (ASCII and binary), so the mesh tests need no files in the repository.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sim/fluid/triangle_mesh.h"

namespace fluidsound::test {

/// The box [lo, hi] as 8 vertices and 12 triangles, counter-clockwise seen from outside.
/// Vertex v has corner bits (x, y, z) = (v & 1, v >> 1 & 1, v >> 2 & 1).
inline sim::TriangleMesh boxMesh(const std::array<float, 3>& lo, const std::array<float, 3>& hi) {
  sim::TriangleMesh mesh;
  for (std::uint32_t v = 0; v < 8; ++v)
    mesh.vertices.push_back(
        {(v & 1) ? hi[0] : lo[0], (v & 2) ? hi[1] : lo[1], (v & 4) ? hi[2] : lo[2]});
  // Each face as a quad, counter-clockwise from outside, split into (a, b, c), (a, c, d).
  const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5},   // -x, +x
                                     {0, 1, 5, 4}, {2, 6, 7, 3},   // -y, +y
                                     {0, 2, 3, 1}, {4, 5, 7, 6}};  // -z, +z
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

/// A sphere of radius 1 about the origin: an icosahedron whose triangles are split in four
/// `subdivisions` times, new vertices pushed out to the sphere (10·4ⁿ + 2 vertices, 20·4ⁿ
/// triangles), counter-clockwise seen from outside.
inline sim::TriangleMesh icosphere(int subdivisions) {
  using V = std::array<double, 3>;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<V> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> f = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  const auto normalise = [](V p) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return V{p[0] / n, p[1] / n, p[2] / n};
  };
  for (V& p : v) p = normalise(p);
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      v.push_back(normalise({v[a][0] + v[b][0], v[a][1] + v[b][1], v[a][2] + v[b][2]}));
      const auto index = static_cast<std::uint32_t>(v.size() - 1);
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    for (const auto& tri : f) {
      const std::uint32_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                          ca = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], ab, ca});
      next.push_back({tri[1], bc, ab});
      next.push_back({tri[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = std::move(next);
  }
  sim::TriangleMesh mesh;
  for (const V& p : v)
    mesh.vertices.push_back(
        {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
  mesh.triangles = f;
  return mesh;
}

/// The closed surface swept by turning a closed profile polygon {(r, y)} (r ≥ 0 [m], in order
/// around the cross-section of the material) about the y axis in `segments` steps: one quad
/// (two triangles) per profile edge and step, a fan where an edge ends on the axis (r = 0), no
/// triangles for an edge lying on the axis. Orientation is consistent (the closedness check's
/// requirement); which way round depends on the profile's direction.
inline sim::TriangleMesh revolvedMesh(const std::vector<std::array<double, 2>>& profile, int segments) {
  sim::TriangleMesh mesh;
  std::vector<std::vector<std::uint32_t>> ring(profile.size());  // vertex of each profile point per step
  const double pi = std::acos(-1.0);
  for (std::size_t q = 0; q < profile.size(); ++q) {
    const auto [r, y] = profile[q];
    const int copies = r > 0.0 ? segments : 1;
    for (int s = 0; s < copies; ++s) {
      const double angle = 2.0 * pi * s / segments;
      ring[q].push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
      mesh.vertices.push_back({static_cast<float>(r * std::cos(angle)), static_cast<float>(y),
                               static_cast<float>(r * std::sin(angle))});
    }
  }
  const auto at = [&](std::size_t q, int s) { return ring[q][ring[q].size() == 1 ? 0 : s % segments]; };
  for (std::size_t q = 0; q < profile.size(); ++q) {
    const std::size_t n = (q + 1) % profile.size();
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t a0 = at(q, s), a1 = at(q, s + 1), b0 = at(n, s), b1 = at(n, s + 1);
      if (a0 != a1) mesh.triangles.push_back({a0, a1, b1});
      if (b0 != b1) mesh.triangles.push_back({a0, b1, b0});
    }
  }
  return mesh;
}

/// A drinking glass standing on y = 0, axis +y through x = z = 0: outer radius innerRadius +
/// wall, inner radius innerRadius, height `height`, base `base` thick, open at the top [m].
inline sim::TriangleMesh glassMesh(double innerRadius, double wall, double height, double base, int segments) {
  const double outer = innerRadius + wall;
  return revolvedMesh({{0.0, 0.0}, {outer, 0.0}, {outer, height}, {innerRadius, height}, {innerRadius, base},
                       {0.0, base}},
                      segments);
}

/// Writes `text` to `path` as it is (binary mode: no newline translation).
inline void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

/// The mesh as OBJ text: `v` lines with 9 significant digits (floats read back exactly), `f`
/// lines counting from 1.
inline std::string objText(const sim::TriangleMesh& mesh) {
  std::string text = "# written by tests/support/test_meshes.h\n";
  char line[128];
  for (const auto& p : mesh.vertices) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
    text += line;
  }
  for (const auto& t : mesh.triangles) {
    std::snprintf(line, sizeof line, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
    text += line;
  }
  return text;
}

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

/// The mesh as PLY: float x y z plus a float `confidence` to skip, a uchar/int `vertex_indices`
/// list, and an element `edge` with no items (readers must skip both).
inline std::string plyText(const sim::TriangleMesh& mesh, PlyEncoding encoding) {
  const char* format = encoding == PlyEncoding::Ascii                ? "ascii"
                       : encoding == PlyEncoding::BinaryLittleEndian ? "binary_little_endian"
                                                                     : "binary_big_endian";
  std::string text =
      std::string("ply\r\nformat ") + format + " 1.0\r\ncomment test mesh\r\n" + "element vertex " +
      std::to_string(mesh.vertices.size()) + "\r\n" +
      "property float x\r\nproperty float y\r\nproperty float z\r\n" +
      "property float confidence\r\n" + "element face " + std::to_string(mesh.triangles.size()) +
      "\r\n" + "property list uchar int vertex_indices\r\n" +
      "element edge 0\r\nproperty int vertex1\r\nproperty int vertex2\r\n" + "end_header\n";
  const bool swap =
      (encoding == PlyEncoding::BinaryBigEndian) == (std::endian::native == std::endian::little);
  const auto put = [&](const void* data, std::size_t size) {
    char bytes[8];
    std::memcpy(bytes, data, size);
    if (swap) std::reverse(bytes, bytes + size);
    text.append(bytes, size);
  };
  char line[128];
  for (const auto& p : mesh.vertices) {
    if (encoding == PlyEncoding::Ascii) {
      std::snprintf(line, sizeof line, "%.9g %.9g %.9g 1\n", p[0], p[1], p[2]);
      text += line;
    } else {
      const float confidence = 1.0f;
      for (float c : p) put(&c, 4);
      put(&confidence, 4);
    }
  }
  for (const auto& t : mesh.triangles) {
    if (encoding == PlyEncoding::Ascii) {
      std::snprintf(line, sizeof line, "3 %u %u %u\n", t[0], t[1], t[2]);
      text += line;
    } else {
      const std::uint8_t three = 3;
      put(&three, 1);
      for (std::uint32_t i : t) {
        const auto index = static_cast<std::int32_t>(i);
        put(&index, 4);
      }
    }
  }
  return text;
}

}  // namespace fluidsound::test
