// acoustics/transfer/wave_air_field.h — the geometric transfer's air side with the geometry in
// place (issue 20; shared transfer.md §4): for one frame and one listener, p_L near the liquid
// surface at every frequency up to the air grid's limit, from one wave solve (air_wave_solve.h) on
// the frame's grid merged to a coarser air grid. docs/transfer.md, "The air side".
#pragma once

#include <complex>
#include <optional>
#include <unordered_map>
#include <vector>

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/transfer/water_grid.h"

namespace fluidsound::acoustics {

/// Settings of the air side's wave solve (the scene's transfer.air_* fields).
struct WaveAirOptions {
  /// The air grid's cell [m]: the frame's cells merged by the largest whole factor that divides
  /// every count and keeps the cell at most this. Frequencies up to c_a/(6h_a) are solved
  /// (5.7 kHz at 1 cm); above, the rigid-surface air field.
  double cellSize = 0.01;
  /// Seconds between air solves; a frame uses the solve nearest its time. The air side changes
  /// as the glass fills, slowly against the frame rate.
  double interval = 0.25;
  /// Sound simulated after the pulse has crossed the grid [s]: the air column's ring.
  double ringTime = 0.03;
  /// Cells of absorbing layer around the air grid. 6 (6 cm at 1 cm): the glass pour's 1 cm air grid
  /// is 16 × 20 × 16 cells, so a 10-cell layer made 90 % of the cells it steps; the
  /// WaveAirField tests measure the same figures with 6 as with 10.
  int absorbingCells = 6;
};

/// @brief The grid with `factor`³ cells merged into one (`factor` divides every count): φ and the
///        open volume are the block means; a merged face's open fraction is the mean, over its
///        factor² columns of fine cells, of the least open fine face the column crosses between
///        the two merged centres; a merged cell that a wall crosses (a closed fine face inside
///        it) is shut, so a thin wall becomes at most one merged cell thick and never leaks.
WaterGrid mergedGrid(const WaterGrid& grid, int factor);

/// @brief The height y [m] of a rigid horizontal plane that every column on the grid's four
///        vertical sides shares (liquid or closed below, open air above: a table or a liquid
///        reaching the sides), or nothing when the sides differ.
std::optional<double> groundPlaneHeight(const WaterGrid& grid);

/// One frame's air side for one listener.
class WaveAirField {
 public:
  /// @brief Solves the air of `frame` (y up) for a unit volume-velocity source at `listener`.
  WaveAirField(const WaterGrid& frame, const Vec3& listener, const AirProperties& air,
               const WaveAirOptions& options);

  /// Highest frequency solved [Hz].
  double maxFrequency() const { return maxFrequency_; }
  /// @brief p_L [Pa per m³/s] at x [m] and ω [rad/s]: the air cell holding x, or the nearest
  ///        one near the liquid within one cell, read between frequency bins; nothing above
  ///        maxFrequency() or where no solved cell is near.
  std::optional<std::complex<double>> at(const Vec3& x, double angularFrequency) const;
  /// Memory the field holds [bytes]: its spectra and grid.
  std::size_t bytes() const;

 private:
  WaterGrid grid_;  ///< the merged air grid (φ, faces), for locating points
  Vec3 listener_{};
  AirProperties air_;
  double maxFrequency_ = 0.0, binSpacing_ = 0.0;
  std::unordered_map<std::size_t, std::size_t> probeOfCell_;
  /// Where each probe's value holds: on the liquid surface (the face between the probe's cell
  /// and a liquid neighbour) where it was extrapolated there, else the cell's centre.
  std::vector<Vec3> probePoint_;
  /// [probe][bin]: p_L·e^{+ik_a R}, R from the listener to the probe's point (smooth in ω).
  std::vector<std::vector<std::complex<float>>> spectrum_;
};

}  // namespace fluidsound::acoustics
