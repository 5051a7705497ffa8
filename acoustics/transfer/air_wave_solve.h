// acoustics/transfer/air_wave_solve.h — the air side of the geometric transfer with the frame's
// geometry in place (issue 20; shared transfer.md §4): p_L, the air pressure at given points from a
// unit volume-velocity source at a listener, with the liquid surface and every solid rigid (water
// is ~3600× stiffer than air). One time-domain solve gives every frequency at once.
//
// Method: the scattered field p_s = p − p_inc on the frame's grid, staggered (pressure at cell
// centres, normal velocity at faces; Yee 1966 in its acoustic form), second order in space and
// time. p_inc is the free field of the listener's monopole, known in closed form wherever the
// listener is (outside the grid, a metre away, as scenes place them). On the rigid part of each
// face (a closed or partly closed face, the projection's variational fractions; every face between
// air and liquid) the scattered normal velocity cancels the incident one. Around the grid, a
// graded absorbing layer in which the geometry continues as it is at the grid's edge (a table or a
// water surface reaching the edge goes on). The source's volume velocity is a Gaussian pulse; the
// pressure at the probes is Fourier-transformed on the fly and divided by the pulse's spectrum.
// docs/transfer.md, "The air side".
#pragma once

#include <complex>
#include <optional>
#include <span>
#include <vector>

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/transfer/water_grid.h"

namespace fluidsound::acoustics {

/// An infinite rigid plane x_axis = position [m] (axis 0, 1, 2 = x, y, z).
struct RigidPlane {
  int axis = 0;
  double position = 0.0;
};

/// At most this many monopoles in the known field: the listener and its images in three planes.
inline constexpr std::size_t kMaxKnownSources = 8;

/// Settings of one air-side solve.
struct AirWaveOptions {
  /// Highest frequency [Hz] asked for: the pulse's spectrum is 10⁻³ of its peak there. The
  /// grid must resolve it (the caller keeps it below c_a/(6h)).
  double maxFrequency = 4000.0;
  /// Simulated time [s] after the pulse has crossed the grid: long enough for the slowest
  /// resonance to ring down (a quarter-wave air column of Q ≈ 30 at 700 Hz: ~40 ms).
  double ringTime = 0.05;
  /// Cells of absorbing layer beyond each side of the grid.
  int absorbingCells = 16;
  /// Courant number c·Δt·√3/h, ≤ 1 for stability.
  double courant = 0.9;
  /// A rigid plane y = groundHeight [m] under the whole scene (the liquid's level or the table
  /// it stands on, continued beyond the grid): the known field is then the source plus its mirror
  /// image in the plane, and the solve finds only what the rest of the geometry scatters, which
  /// leaves through the absorbing layer. Without it the known field is the free field alone.
  std::optional<double> groundHeight;
  /// Rigid walls that go on beyond the grid (a room's or a long tank's), at right angles to the
  /// ground and to each other (one per axis, not y when there is a ground): the known field holds
  /// the images in them too, so the layer need not absorb their reflection of the source. A wall
  /// the grid holds but this list does not name is cut off at the grid's edge.
  std::vector<RigidPlane> walls;
};

/// @brief p_L [Pa per m³/s] at each probe point and angular frequency, from a unit volume-velocity
///        monopole at `listener`, the grid's liquid (φ < 0) and closed faces rigid. Each probe
///        reads the air cell that holds it, or the nearest air cell among its 6 neighbours (a
///        point on the liquid surface); a probe with no air cell there reads 0.
/// @return [probe][frequency], p_L = p_s + p_inc with the e^{+iωt} convention of the transfer
///         stage (p_inc = iωρ_a e^{−ik_a R}/(4πR), plus its image in the ground plane if any)
std::vector<std::vector<std::complex<double>>> airSidePressure(
    const WaterGrid& grid, const Vec3& listener, std::span<const Vec3> probes,
    std::span<const double> angularFrequencies, const AirProperties& air,
    const AirWaveOptions& options);

/// p_L at many points on a regular grid of frequencies, from one solve.
struct AirSideSpectra {
  double binSpacing = 0.0;  ///< Δf [Hz]: bin q is at q·Δf
  /// [probe][bin], bins 0 … the last at or below options.maxFrequency; p_L as airSidePressure
  /// gives it. Empty for a probe with no air cell.
  std::vector<std::vector<std::complex<double>>> pressure;
};

/// @brief airSidePressure on the bins of a fast Fourier transform (Eigen's, kissfft) of the whole
///        run, zero-padded to at least twice its length: for many probes and frequencies at once.
AirSideSpectra airSideSpectra(const WaterGrid& grid, const Vec3& listener,
                              std::span<const Vec3> probes, const AirProperties& air,
                              const AirWaveOptions& options);

}  // namespace fluidsound::acoustics
