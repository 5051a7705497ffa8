// sim/fluid/simulation_failure.h — the solver's state stopped being a flow: a velocity that is not a
// finite number, or a time step too short to advance the clock (the solver blew up). Neither a
// bad input nor a bug in the checks: the CLI reports it with its own exit code (docs/cli.md).
#pragma once

#include <stdexcept>
#include <string>

#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particles.h"

namespace fluidsound::sim {

/// @brief The simulation cannot continue. what() is one line naming the time and the place.
class SimulationFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// @brief Throws SimulationFailure naming the first particle (in storage order, so the same one on
///        any thread count) whose velocity has a component that is not finite, with its position.
/// @param time  the solver's time [s], for the message
void requireFiniteParticleVelocities(const Particles& particles, double time);

/// @brief Throws SimulationFailure naming the first face (grid order) whose velocity is not
///        finite, by its axis, index and centre [m].
/// @param stage  what produced the velocities, for the message (e.g. "pressure projection")
void requireFiniteFaceVelocities(const MacVelocity& velocity, const GridGeometry& grid, double time,
                                 const char* stage);

/// @brief Throws SimulationFailure if time + dt does not exceed time (a step of zero or below the
///        clock's resolution: some particle moves at ∞ or at a speed whose float square is ∞,
///        from 1.8e19 m/s), naming the fastest particle, its position and speed.
/// @param dt  the CFL time step [s] the speeds gave
void requireTimeAdvances(const Particles& particles, double time, double dt);

/// "(x, y, z) m" with 4 decimals (0.1 mm): a position in a failure message.
std::string positionText(double x, double y, double z);

}  // namespace fluidsound::sim
