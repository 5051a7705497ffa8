// tests/support/water_grid_shapes.h — acoustics::WaterGrid builders for the geometric transfer's
// reference geometries (docs/transfer.md, "Reference solutions and their tests"): a rectangular
// box of water, the same with a rigid wall plane inside it, a filled cylindrical tank and a
// filled hemispherical bowl. Each is an analytic solid plus a horizontal free surface y = y_s
// (+y is up): the face open fractions are the fraction of a face's sample points outside the
// solid, φ at every cell centre is the plane distance y − y_s (cells inside the solid keep their
// φ < 0; the solver ignores closed cells).
#pragma once

#include <array>
#include <functional>
#include <utility>

#include "acoustics/transfer/water_grid.h"
#include "sim/core/vec3.h"

namespace fluidsound::test {

/// Frames that are all the same grid (a still body of water in the transfer stage's tests).
class SameGridEveryFrame : public acoustics::FrameWaterGrids {
 public:
  explicit SameGridEveryFrame(acoustics::WaterGrid grid) : grid_(std::move(grid)) {}
  acoustics::WaterGrid open(int) const override { return grid_; }

 private:
  acoustics::WaterGrid grid_;
};

/// An analytic solid: a signed distance [m] (or any function with its sign), < 0 inside.
using SolidDistance = std::function<double(const Vec3&)>;

/// The grid a shape lives on: cells, cell size [m], minimum corner [m], open sides.
struct WaterGridFrame {
  std::array<int, 3> cells{1, 1, 1};
  double cellSize = 0.0;
  Vec3 origin{};
  std::array<bool, 6> openSides{false, false, false, true, false, false};
};

/// @brief The water grid of `frame` with the free surface y = `surfaceHeight` [m] and `solid`:
///        φ = y − y_s at the cell centres; each face's open fraction is the fraction of its
///        samplesPerSide² points (cell-centred sub-grid) outside the solid.
acoustics::WaterGrid waterGridFromSolid(const WaterGridFrame& frame, double surfaceHeight,
                                        const SolidDistance& solid, int samplesPerSide = 6);

/// A rectangular box of water: floor at y = 0 (the grid's −y side), the side walls the grid's
/// ±x, ±z sides (rigid), the surface at y = depth, `airCells` cell layers of air above it up to
/// the open +y side. Width and length must be whole numbers of cells.
struct WaterBoxShape {
  double width = 0.1;    ///< L_x [m]
  double depth = 0.07;   ///< H [m], floor to surface
  double length = 0.02;  ///< L_z [m]
  double cellSize = 0.005;
  int airCells = 2;
};

/// @throws std::invalid_argument when width or length is not a whole number of cells
acoustics::WaterGrid waterBox(const WaterBoxShape& box);

/// The box with a rigid solid filling x < wallX [m] below the surface: its water is the box
/// x ∈ [wallX, width]. The wall does not continue into the air (the air side is a rigid plane).
acoustics::WaterGrid waterBoxWithWall(const WaterBoxShape& box, double wallX);

/// A vessel filled to its rim, set in a rigid baffle: the solid is everything below the rim
/// (y < rimHeight) outside the vessel's cavity; above the rim is air. The grid holds the cavity
/// with `marginCells` of solid around it and `airCells` layers above the rim; the vessel's axis
/// is the vertical line x = z = 0 and its rim at y = rimHeight.
struct VesselShape {
  double radius = 0.05;    ///< a [m]
  double depth = 0.10;     ///< h [m], rim to floor (the cylinder; the bowl's depth is its radius)
  double rimHeight = 0.0;  ///< y_s [m]
  double cellSize = 0.005;
  int marginCells = 1;
  int airCells = 2;
  /// Where the rim lies in its cell layer, as a fraction of a cell above the layer's lower face
  /// (0.3: the surface crosses between cell centres, not on a face or a centre).
  double rimCellFraction = 0.3;
};

/// A rigid cylindrical tank: cavity r < a, rim − h < y.
acoustics::WaterGrid cylindricalTank(const VesselShape& vessel);

/// A hemispherical bowl: cavity the ball of radius a centred on the rim's centre (0, y_s, 0),
/// below the rim; the flat surface passes through the centre. `depth` is ignored.
acoustics::WaterGrid hemisphericalBowl(const VesselShape& vessel);

/// A thin rigid tube of `radius` [m] standing on a flat liquid (y < 0) up to y = `top` [m], axis
/// x = z = 0, at `cellSize` cells over x, z ∈ [−0.06, 0.06] m and y from −0.02 m to 7 cm above the
/// top: every x- and z-face between a cell centre inside the radius and one outside is closed
/// between y = 0 and the top (a staircase wall of no thickness; the air side's glass).
acoustics::WaterGrid tubeOnLiquid(double radius, double top, double cellSize);

}  // namespace fluidsound::test
