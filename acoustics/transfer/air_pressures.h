// acoustics/transfer/air_pressures.h — p_L, the air side of the geometric transfer, at every air
// point of a frame's water grid for one listener and frequency: the wave solve's where it answers,
// else the rigid-surface field (docs/transfer.md, "The air side").
#pragma once

#include <vector>

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/transfer/water_helmholtz.h"
#include "acoustics/transfer/wave_air_field.h"

namespace fluidsound::acoustics {

/// @brief p_L at each of water.airPoints() from a unit volume-velocity source at `listener` at
///        angular frequency `omega` [rad/s]: `wave` where it answers (may be null), else
///        rigidSurfaceAirPressure.
std::vector<Complex> airPressures(const WaterHelmholtz& water, const Vec3& listener, double omega,
                                  const AirProperties& air, const WaveAirField* wave = nullptr);

}  // namespace fluidsound::acoustics
