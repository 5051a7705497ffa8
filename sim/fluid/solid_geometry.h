// sim/fluid/solid_geometry.h — pressure projection input: the scene's solids (domain walls, boxes,
// spheres) as a signed distance on the grid nodes, the variational face-area weights derived from
// it (Batty, Bertails & Bridson 2007, §3), and the velocity of kinematic solids on the faces.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "sim/fluid/array3.h"
#include "sim/fluid/fluid_scene.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/scene_mesh_distances.h"

namespace fluidsound::sim {

/// Signed distances within this fraction of the cell size of zero are set to exactly zero, so a
/// wall or box face meant to lie on a grid plane lies on it despite the rounding of world
/// coordinates (≈ 1e-16·|x|/h, far below this) and a face in that plane is closed (see
/// faceOpenFractions). Features thinner than 1e-6·h are not resolved by the grid anyway.
inline constexpr double kSolidSnapFraction = 1e-6;

/// @brief Signed distance [m] from each grid node (cell corner (i, j, k)·h + origin) to the solid
///        region, negative inside solid: the minimum over
///        - each closed face of the domain box (Domain::open false): the distance to the wall's
///          plane, negative beyond it, so everything behind a closed wall is solid. A closed wall
///          is placed at the domain face or at the grid's boundary, whichever is further inside,
///          so the grid's boundary faces are always closed there. Exact inside the domain; outside
///          it the value is the deepest penetration of one wall (a bound, not Euclidean);
///        - boxes: exact signed distance of the oriented box: scaled about the world origin,
///          rotated by rotateDegrees (about x, then y, then z: R = Rz·Ry·Rx) about the scaled
///          box's centre, translated by translate plus the path translation at `time`;
///        - spheres: exact; centre scaled about the origin, radius scaled, then translated;
///        - meshes: their node distance (solidMeshes) interpolated at the node moved back by the
///          path translation at `time`.
///        Values within kSolidSnapFraction·h of zero are set to 0.
/// @param grid    node positions: origin + (i, j, k)·cellSize, i = 0 … ni
/// @param domain  closed faces become walls
/// @param solids  static or kinematic solids (Solid::path)
/// @param time    [s], the time at which kinematic solids are placed
/// @return Array3f of size grid.nodeCount(), [m]
/// @param solidMeshes  the mesh solids' node distances on `grid`, one entry per solid
///                     (SceneMeshDistances::solids); may be empty when no solid is a mesh
/// @throws std::invalid_argument for a MeshFile solid whose distance solidMeshes does not hold
Array3f solidNodeDistance(const GridGeometry& grid, const Domain& domain,
                          std::span<const Solid> solids, double time,
                          std::span<const MeshNodeDistance> solidMeshes = {});

/// @brief The solid distance at the centre of cell (i, j, k) [m]: the mean of its 8 nodal
///        distances, summed in float in corner order. A cell whose value is < 0 has its centre
///        inside a solid — the solver's one rule for solid cells (pressure extension, level set,
///        thin-wall faces).
inline float cellCentreSolidDistance(const Array3f& solidNodes, int i, int j, int k) {
  float sum = 0.0f;
  for (int c = 0; c < 8; ++c) sum += solidNodes(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2));
  return sum / 8.0f;
}

/// @brief Fraction [0, 1] of a triangle inside the solid (φ ≤ 0), φ linear over the triangle and
///        given at its vertices. Exact for a linear φ.
double solidFractionOfTriangle(double phi0, double phi1, double phi2);

/// @brief Fraction [0, 1] of a square inside the solid (φ ≤ 0) from its corner values, corners in
///        cyclic order. The square is split into four triangles about its centre, where φ is the
///        mean of the corners, and solidFractionOfTriangle is averaged; this is exact when φ is
///        linear (a plane cut) and resolves the saddle case of marching squares by the centre
///        value. (Batty's Fluid3D `fraction_inside` enumerates marching-squares cases instead;
///        both give the same area for a plane cut.)
/// @note φ ≤ 0 counts as solid, so a face lying in a solid's surface (all corners 0) is closed:
///       a wall that coincides with a grid plane lets nothing through.
double solidFractionOfSquare(double phi00, double phi10, double phi11, double phi01);

/// @brief Variational face weights (Batty, Bertails & Bridson 2007, eq. 8): for every MAC face,
///        the fraction of its area NOT inside solid, from the nodal distances at its 4 corners.
/// @param solidNodeDistance  solidNodeDistance(...) [m], size grid.nodeCount()
/// @return per axis (0 = u, 1 = v, 2 = w) an Array3f of size grid.faceCount(axis), in [0, 1]:
///         1 = fully open (liquid may cross), 0 = fully inside solid.
std::array<Array3f, 3> faceOpenFractions(const Array3f& solidNodeDistance,
                                         const GridGeometry& grid);

/// @brief Translation [m] of a kinematic solid's path at `time`: linear between keys, held at the
///        first key before it and at the last key after it; zero for an empty path.
Vec3 pathTranslation(const std::vector<PathKey>& path, double time);

/// @brief Velocity [m/s] of a path at `time`: the slope of the segment [t_k, t_{k+1}) holding
///        `time` (piecewise constant, right-continuous); zero before the first key, from the last
///        key on and for fewer than two keys.
Vec3 pathVelocity(const std::vector<PathKey>& path, double time);

/// @brief Velocity [m/s] of the solid at each MAC face, the normal component of that face
///        (u on x-faces, …): the velocity of the nearest solid at the face centre, by the same
///        distances as solidNodeDistance; domain walls and solids without a path are at rest.
///        Used by the pressure projection as u_solid on the covered part (1 − weight) of a face.
/// @return per axis an Array3f of size grid.faceCount(axis) [m/s]; all zero when no solid moves
/// @param solidMeshes  as solidNodeDistance
/// @throws std::invalid_argument for a MeshFile solid whose distance solidMeshes does not hold
std::array<Array3f, 3> solidFaceVelocity(const GridGeometry& grid, const Domain& domain,
                                         std::span<const Solid> solids, double time,
                                         std::span<const MeshNodeDistance> solidMeshes = {});

}  // namespace fluidsound::sim
