// sim/fluid/solid_geometry.cpp — see solid_geometry.h.
#include "sim/fluid/solid_geometry.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <variant>

#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/solid_rotation.h"

namespace fluidsound::sim {
namespace {


/// Rᵀ·v: local coordinates of a world offset (R is orthonormal).
Vec3 localFromWorld(const Mat3& worldFromLocal, const Vec3& v) {
  Vec3 r{};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) r[j] += worldFromLocal[i][j] * v[i];
  return r;
}

}  // namespace

namespace {

/// A box or sphere solid placed at one time, ready for distance queries.
struct PlacedSolid {
  bool isBox = false;
  Vec3 centre{};          ///< [m]
  Mat3 worldFromLocal{};  ///< box orientation
  Vec3 halfExtent{};      ///< box half sizes [m]
  double radius = 0.0;    ///< sphere radius [m]
  Vec3 velocity{};        ///< [m/s]

  const MeshNodeDistance* mesh =
      nullptr;  ///< a mesh's distance (centre = its path translation), else null

  double distance(const Vec3& p) const {
    const Vec3 d{p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
    if (mesh != nullptr) return meshDistance(*mesh, d);
    if (!isBox) return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - radius;
    const Vec3 q = localFromWorld(worldFromLocal, d);
    double outsideSquared = 0.0;
    double insideMax = -std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      const double e = std::abs(q[a]) - halfExtent[a];
      outsideSquared += e > 0.0 ? e * e : 0.0;
      insideMax = std::max(insideMax, e);
    }
    return std::sqrt(outsideSquared) + std::min(insideMax, 0.0);
  }
};

std::vector<PlacedSolid> placeSolids(std::span<const Solid> solids, double time,
                                     std::span<const MeshNodeDistance> solidMeshes) {
  std::vector<PlacedSolid> placed;
  placed.reserve(solids.size());
  for (std::size_t n = 0; n < solids.size(); ++n) {
    const Solid& solid = solids[n];
    const Vec3 path = pathTranslation(solid.path, time);
    PlacedSolid s;
    s.velocity = pathVelocity(solid.path, time);
    if (const MeshNodeDistance* mesh = meshEntry(solid.shape, solidMeshes, n)) {
      s.mesh = mesh;
      s.centre = path;  // the mesh is placed by scale and translation already; the path shifts it
    } else if (const Box* box = std::get_if<Box>(&solid.shape)) {
      s.isBox = true;
      s.worldFromLocal = rotationFromEulerDegrees(solid.rotateDegrees);
      for (int a = 0; a < 3; ++a) {
        s.centre[a] =
            0.5 * solid.scale * (box->min[a] + box->max[a]) + solid.translate[a] + path[a];
        s.halfExtent[a] = 0.5 * solid.scale * (box->max[a] - box->min[a]);
      }
    } else {
      const Sphere& sphere = std::get<Sphere>(solid.shape);
      for (int a = 0; a < 3; ++a)
        s.centre[a] = solid.scale * sphere.center[a] + solid.translate[a] + path[a];
      s.radius = solid.scale * sphere.radius;
    }
    placed.push_back(s);
  }
  return placed;
}

/// The closed domain faces as half-spaces; distance = min over closed walls, +∞ with none.
struct Walls {
  std::array<bool, 6> closed{};
  std::array<double, 6> plane{};  ///< [m], order −x, +x, −y, +y, −z, +z

  Walls(const GridGeometry& grid, const Domain& domain) {
    for (int a = 0; a < 3; ++a) {
      const double gridMax = grid.origin[a] + grid.cells[a] * grid.cellSize;
      closed[2 * a] = !domain.open[2 * a];
      closed[2 * a + 1] = !domain.open[2 * a + 1];
      plane[2 * a] = std::max(domain.min[a], grid.origin[a]);  // further inside of the two
      plane[2 * a + 1] = std::min(domain.max[a], gridMax);
    }
  }
  double distance(const Vec3& p) const {
    double d = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (closed[2 * a]) d = std::min(d, p[a] - plane[2 * a]);
      if (closed[2 * a + 1]) d = std::min(d, plane[2 * a + 1] - p[a]);
    }
    return d;
  }
};

/// Runs body(i, j, k) over an index box, parallel over k slices (each output written once, so
/// the result does not depend on the thread count).
template <typename Body>
void forEachIndex(const Index3& n, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<int>(0, n[2]), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k < r.end(); ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) body(i, j, k);
  });
}

}  // namespace

Vec3 pathTranslation(const std::vector<PathKey>& path, double time) {
  if (path.empty()) return {0.0, 0.0, 0.0};
  if (time <= path.front().time) return path.front().translate;
  if (time >= path.back().time) return path.back().translate;
  const auto next = std::upper_bound(path.begin(), path.end(), time,
                                     [](double t, const PathKey& key) { return t < key.time; });
  const PathKey& a = *(next - 1);
  const PathKey& b = *next;
  const double s = (time - a.time) / (b.time - a.time);
  Vec3 r{};
  for (int c = 0; c < 3; ++c) r[c] = a.translate[c] + s * (b.translate[c] - a.translate[c]);
  return r;
}

Vec3 pathVelocity(const std::vector<PathKey>& path, double time) {
  if (path.size() < 2 || time < path.front().time || time >= path.back().time) return {0, 0, 0};
  const auto next = std::upper_bound(path.begin(), path.end(), time,
                                     [](double t, const PathKey& key) { return t < key.time; });
  const PathKey& a = *(next - 1);
  const PathKey& b = *next;
  Vec3 v{};
  for (int c = 0; c < 3; ++c) v[c] = (b.translate[c] - a.translate[c]) / (b.time - a.time);
  return v;
}

Array3f solidNodeDistance(const GridGeometry& grid, const Domain& domain,
                          std::span<const Solid> solids, double time,
                          std::span<const MeshNodeDistance> solidMeshes) {
  const std::vector<PlacedSolid> placed = placeSolids(solids, time, solidMeshes);
  const Walls walls(grid, domain);
  const double snap = kSolidSnapFraction * grid.cellSize;
  // Far from every solid (no closed wall, no solid): a large positive value, not +∞, so that
  // arithmetic on the field (averages, interpolation) stays finite.
  const double farAway = std::numeric_limits<float>::max();
  Array3f distance(grid.nodeCount());
  forEachIndex(grid.nodeCount(), [&](int i, int j, int k) {
    const Vec3 p = grid.worldFromGrid({double(i), double(j), double(k)});
    double d = std::min(walls.distance(p), farAway);
    for (const PlacedSolid& s : placed) d = std::min(d, s.distance(p));
    distance(i, j, k) = static_cast<float>(std::abs(d) < snap ? 0.0 : d);
  });
  return distance;
}

double solidFractionOfTriangle(double phi0, double phi1, double phi2) {
  const std::array<double, 3> phi{phi0, phi1, phi2};
  int insideCount = 0;
  for (double p : phi) insideCount += p <= 0.0 ? 1 : 0;
  if (insideCount == 0) return 0.0;
  if (insideCount == 3) return 1.0;
  // Rotate so that vertex 0 is the odd one out (the lone inside or the lone outside vertex).
  const bool loneIsInside = insideCount == 1;
  int lone = 0;
  while ((phi[lone] <= 0.0) != loneIsInside) ++lone;
  const double a = phi[lone], b = phi[(lone + 1) % 3], c = phi[(lone + 2) % 3];
  // The zero level cuts edges (a, b) and (a, c) at fractions a/(a − b) and a/(a − c) from a;
  // the corner triangle at a has area (a/(a − b))·(a/(a − c)) of the whole (similar triangles).
  const double corner = (a / (a - b)) * (a / (a - c));
  return loneIsInside ? corner : 1.0 - corner;
}

double solidFractionOfSquare(double phi00, double phi10, double phi11, double phi01) {
  const double centre = 0.25 * (phi00 + phi10 + phi11 + phi01);
  return 0.25 * (solidFractionOfTriangle(centre, phi00, phi10) +
                 solidFractionOfTriangle(centre, phi10, phi11) +
                 solidFractionOfTriangle(centre, phi11, phi01) +
                 solidFractionOfTriangle(centre, phi01, phi00));
}

std::array<Array3f, 3> faceOpenFractions(const Array3f& solidNodeDistance,
                                         const GridGeometry& grid) {
  std::array<Array3f, 3> open;
  for (int a = 0; a < 3; ++a) {
    open[a] = Array3f(grid.faceCount(a));
    // The face normal to axis a spans the other two axes b and c; its corners in cyclic order
    // are base, base + e_b, base + e_b + e_c, base + e_c, with base = the face's own index.
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    Index3 eb{0, 0, 0}, ec{0, 0, 0};
    eb[b] = 1;
    ec[c] = 1;
    Array3f& out = open[a];
    forEachIndex(out.size(), [&](int i, int j, int k) {
      const auto& phi = solidNodeDistance;
      const double solid =
          solidFractionOfSquare(phi(i, j, k), phi(i + eb[0], j + eb[1], k + eb[2]),
                                phi(i + eb[0] + ec[0], j + eb[1] + ec[1], k + eb[2] + ec[2]),
                                phi(i + ec[0], j + ec[1], k + ec[2]));
      out(i, j, k) = static_cast<float>(std::clamp(1.0 - solid, 0.0, 1.0));
    });
  }
  return open;
}

std::array<Array3f, 3> solidFaceVelocity(const GridGeometry& grid, const Domain& domain,
                                         std::span<const Solid> solids, double time,
                                         std::span<const MeshNodeDistance> solidMeshes) {
  const std::vector<PlacedSolid> placed = placeSolids(solids, time, solidMeshes);
  std::array<Array3f, 3> velocity{Array3f(grid.faceCount(0)), Array3f(grid.faceCount(1)),
                                  Array3f(grid.faceCount(2))};
  const bool anyMoving = std::any_of(placed.begin(), placed.end(), [](const PlacedSolid& s) {
    return s.velocity[0] != 0.0 || s.velocity[1] != 0.0 || s.velocity[2] != 0.0;
  });
  if (!anyMoving) return velocity;
  const Walls walls(grid, domain);
  for (int a = 0; a < 3; ++a) {
    Array3f& out = velocity[a];
    forEachIndex(out.size(), [&](int i, int j, int k) {
      Vec3 g{i + 0.5, j + 0.5, k + 0.5};
      g[a] -= 0.5;  // the face of axis a sits on the cell's lower a-boundary
      const Vec3 p = grid.worldFromGrid(g);
      double nearest = walls.distance(p);  // walls are at rest
      double v = 0.0;
      for (const PlacedSolid& s : placed) {
        const double d = s.distance(p);
        if (d < nearest) {
          nearest = d;
          v = s.velocity[a];
        }
      }
      out(i, j, k) = static_cast<float>(v);
    });
  }
  return velocity;
}

}  // namespace fluidsound::sim
