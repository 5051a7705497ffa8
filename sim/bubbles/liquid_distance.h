// sim/bubbles/liquid_distance.h — bubble model input: the true signed distance to the free surface,
// rebuilt from the solver's liquid field. The solver's φ (Zhu & Bridson 2005, liquid_surface.h)
// is a distance only within about a particle radius of the surface; deeper it stays near −r, so it
// cannot give a particle's or a bubble's depth.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"

namespace fluidsound::sim {

/// @brief The signed distance to the surface where φ = 0, negative in the liquid (φ < 0):
///        on the grid within a band of the surface, and exactly (to the surface points) anywhere.
///
/// Surface points: each cell next to the surface (a 6-neighbour of the other phase) holds the foot
/// of its perpendicular on the plane through its nearest crossing per axis, each crossing placed
/// by linear interpolation of φ between the two centres (the surface the interpolant of φ
/// describes). Band field: every cell within `band` of a surface point gets the distance to the
/// nearest surface point (each point lowers the squared distance of the cells within the band
/// around it: exact to the points, in any order, so the field does not depend on the threads); a
/// cell next to the surface keeps the distance to its own point.
/// Cells further away hold ±band. Exact for a plane; elsewhere within the first layer's O(h) error
/// (tests/sim/bubbles/liquid_distance_test.cpp).
///
/// Cells whose centre is inside a solid (their 8 nodal solid distances sum < 0, the solver's
/// extendIntoSolids rule) are neither liquid nor air: they make no surface with their neighbours,
/// distances pass through them, and they count as liquid in the sign.
class SurfaceDistance {
 public:
  SurfaceDistance() = default;
  /// @param phi                the solver's liquid field at cell centres [m]; only its sign and
  ///                           its values at the cells next to the surface are read
  /// @param solidNodeDistance  solid signed distance at the nodes [m]
  /// @param band               [m], > 0: how far from the surface the grid field is computed
  ///                           (on the liquid side)
  /// @param airBand            [m], in (0, band]: the same on the air side; 0 for `band`
  /// @throws std::invalid_argument for a band ≤ 0 or an airBand outside (0, band]
  SurfaceDistance(const Array3f& phi, const Array3f& solidNodeDistance, const GridGeometry& grid,
                  double band, double airBand = 0.0);

  /// @brief As the constructor, reusing this object's memory (the bubble model rebuilds the
  ///        distance on every substep).
  void rebuild(const Array3f& phi, const Array3f& solidNodeDistance, const GridGeometry& grid,
               double band, double airBand = 0.0);

  /// Signed distance at cell centres [m], exact to the surface points within the band of its side,
  /// −band or +airBand beyond.
  const Array3f& field() const { return field_; }
  double band() const { return band_; }
  double airBand() const { return airBand_; }
  /// The surface points [m] (one per cell next to the surface).
  const std::vector<Vec3>& surfacePoints() const { return points_; }

  /// @brief Signed distance at any position [m]: the trilinear interpolant of field() where its 8
  ///        centres lie inside the band, else ± the distance to the nearest surface point (sign
  ///        of the interpolant). Without any surface point, ± the grid's diagonal.
  double at(const Vec3& position) const;

 private:
  /// Distance [m] from p to the nearest surface point, by rings of buckets around p's bucket.
  double nearestSurfacePoint(const Vec3& p) const;
  /// A cell: its linear index in the grid, and its indices per axis.
  struct Cell {
    std::uint32_t grid;
    std::int16_t i, j, k;
  };
  /// The cells whose centre may lie within the band of a point: [lo, hi] per axis.
  struct Reach {
    std::int16_t lo[3], hi[3];
  };
  /// A cell next to the surface, the distance [m] to its surface point, the point [m], and the
  /// cells it reaches.
  struct SurfaceCell {
    Cell cell;
    double distance;
    Vec3 point;
    Reach reach;
  };

  /// A row's work buffers while finding surface cells: the crossing test per cell, and the row's
  /// phases with a solid cell either side.
  struct RowScratch {
    std::vector<std::uint8_t> crossing, padded;
  };

  // rebuild's steps, in order (each reads what the ones before wrote).
  /// solidCells_ from the nodal solid distances, when they changed.
  void findSolidCells(const Array3f& solidNodeDistance);
  /// phase_ and rowPhases_ from φ and the solid cells; the field at ±band of each cell's side.
  void classifyCells(const Array3f& phi);
  /// surface_: every cell next to the surface with its point, in cell order.
  void findSurfaceCells(const Array3f& phi);
  /// The field within the band: the nearest surface point's distance, signed by the phase.
  void fillBand();
  /// points_ and bucketStart_ from surface_, for at().
  void groupPointsByBucket();

  // Their parts.
  int planesPerTask() const;
  Reach reachOf(const Vec3& p) const;
  void findSurfaceCellsOfRow(const Array3f& phi, int j, int k, RowScratch& scratch);
  SurfaceCell surfaceCellAt(const Array3f& phi, int i, int j, int k) const;
  /// Lowers nearest2_ in z-planes [kBegin, kEnd) by the surface cells [first, last).
  void lowerNearestSquares(int kBegin, int kEnd, std::size_t first, std::size_t last,
                           std::vector<float>& x2);
  /// The field of the rows of z-planes [kBegin, kEnd) that a point reached.
  void writeReachedRows(int kBegin, int kEnd);

  GridGeometry grid_;
  double band_ = 0.0, airBand_ = 0.0;
  Array3f field_;
  std::vector<Vec3> points_;              ///< surface points, grouped by bucket
  Index3 buckets_{0, 0, 0};               ///< bucket counts per axis
  std::vector<std::size_t> bucketStart_;  ///< points of bucket b: [start[b], start[b + 1])
  // Per-cell work arrays of rebuild, kept between rebuilds.
  std::vector<std::uint8_t> phase_;
  std::vector<float> solidNodes_;  ///< the nodal solid distances solidCells_ was found from [m]
  std::vector<std::uint8_t> solidCells_;  ///< 1 for a cell inside a solid
  std::vector<std::uint8_t>
      rowPhases_;  ///< per row of cells (j, k): bit 1 << phase for each phase it holds
  std::vector<std::uint8_t> solidRow_;  ///< a row of solid phases: the neighbours beyond the grid
  std::vector<float> nearest2_;  ///< squared distance to the nearest point, in rows reached [m²]
  std::vector<std::uint8_t> rowReached_;  ///< per row of cells (j, k): 1 once a point reached it
  std::vector<std::size_t> planeStart_;   ///< surface cells of z-plane k: [start[k], start[k + 1])
  std::vector<double> centres_[3];        ///< cell-centre coordinate per index, per axis [m]
  std::vector<std::vector<SurfaceCell>> surfaceOfPlane_;  ///< surface cells found per z-plane
  std::vector<SurfaceCell> surface_;                      ///< all surface cells, in cell order
  std::vector<std::size_t> bucketNext_;  ///< next free slot per bucket while grouping points
};

}  // namespace fluidsound::sim
