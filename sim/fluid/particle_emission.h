// sim/fluid/particle_emission.h — pouring: particles entering the domain through a disk nozzle at the
// scene's flow rate (volume flux = disk area × speed), between the emitter's start and end times.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/particles.h"
#include "sim/fluid/fluid_scene.h"

namespace fluidsound::sim {

/// What an emitter carries from one substep to the next.
struct EmitterState {
  double owed = 0.0;         ///< particles due but not yet emitted (the fraction of one) [-]
  std::uint64_t draws = 0;   ///< random positions drawn so far (the key of the next draw)
  std::size_t emitted = 0;   ///< particles emitted so far
};

/// The grid an emitter pours into and the random stream of its draws (views: the caller keeps
/// them alive during the call).
struct EmissionSetting {
  const GridGeometry& grid;
  const Array3f& solidNodes;     ///< solid signed distance at the nodes [m]; size grid.nodeCount()
  int perCell = 8;               ///< particles per cell volume h³
  std::uint64_t seed = 1;        ///< the scene seed
  std::size_t emitterIndex = 0;  ///< separates the emitters' random streams
};

/// @brief Appends the particles an emitter releases during (t0, t1]: the liquid that flowed out of
///        the disk in that time, π r² · speed · Δt_active of it, at `perCell` particles per cell
///        volume h³ (a running fraction carries over, so the count over any run matches the flux
///        to within one particle). Each particle leaves the disk at a uniformly drawn instant and
///        point of the disk and has travelled speed × (t1 − instant) along the normal by t1; its
///        velocity is speed × normal. Particles that would start inside a solid or outside the
///        grid's box are dropped (and counted as emitted: the nozzle is blocked there, or pours
///        beyond the domain), so every particle appended lies in the domain.
/// @return particles appended
std::size_t emitParticles(Particles& particles, const Emitter& emitter, EmitterState& state,
                          double t0, double t1, const EmissionSetting& setting);

/// Volume [m³] an emitter releases between times a and b: π r² · speed · |[a, b] ∩ [start, end]|.
double emittedVolume(const Emitter& emitter, double a, double b);

}  // namespace fluidsound::sim
