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

/// The strongest resonance of the air over the liquid (a vessel's air column), as the listener
/// drives it: a Lorentzian peak of p_L at the surface over the rigid-surface field.
struct AirResonance {
  double frequency = 0.0;  ///< Ω/2π [Hz]
  double decayRate = 0.0;  ///< β_r [1/s]: the half-power half-width, in rad/s
  double gain = 0.0;       ///< the peak's largest |p_L| over the rigid-surface field's [-]
};

/// Resonances weaker than this gain over the rigid-surface field are not taken as one.
inline constexpr double kMinResonanceGain = 3.0;
/// At most this many resonances are taken, the strongest (a glass's quarter wave and its odd
/// overtones, 3/4 and 5/4 of a wave, lie below 4 kHz while its column is longer than 6 cm).
inline constexpr std::size_t kMaxResonances = 4;
/// Where the air's resonance is looked for [Hz]: a vessel's air column (a glass: 0.3–3 kHz).
inline constexpr double kResonanceLowHz = 200.0, kResonanceHighHz = 4000.0;

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
  /// @brief The peaks between kResonanceLowHz and kResonanceHighHz (or the solve's limit) of
  ///        the largest over the probes of |p_L| ÷ |2 × the free field| (the rigid-surface
  ///        field): each a local maximum of at least kMinResonanceGain whose half-power points
  ///        are both found and whose half-power band does not overlap a stronger one's; the
  ///        kMaxResonances strongest, strongest first.
  std::vector<AirResonance> resonances() const;

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
