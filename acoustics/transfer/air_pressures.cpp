// acoustics/transfer/air_pressures.cpp — see air_pressures.h.
#include "acoustics/transfer/air_pressures.h"

#include <optional>

#include "acoustics/transfer/rigid_surface_air_field.h"

namespace fluidsound::acoustics {

std::vector<Complex> airPressures(const WaterHelmholtz& water, const Vec3& listener, double omega,
                                  const AirProperties& air, const WaveAirField* wave) {
  std::vector<Complex> p;
  p.reserve(water.airPoints().size());
  for (const AirPoint& point : water.airPoints()) {
    const std::optional<Complex> solved = wave ? wave->at(point.position, omega) : std::nullopt;
    p.push_back(solved ? *solved : rigidSurfaceAirPressure(point.position, listener, omega, air));
  }
  return p;
}

}  // namespace fluidsound::acoustics
