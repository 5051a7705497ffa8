// acoustics/transfer/rigid_surface_air_field.cpp — see rigid_surface_air_field.h.
#include "acoustics/transfer/rigid_surface_air_field.h"

#include <cmath>
#include <numbers>

namespace fluidsound::acoustics {

std::complex<double> rigidSurfaceAirPressure(const Vec3& surfacePoint, const Vec3& listener,
                                             double angularFrequency, const AirProperties& air) {
  const double r = std::hypot(surfacePoint[0] - listener[0], surfacePoint[1] - listener[1],
                              surfacePoint[2] - listener[2]);
  if (r == 0.0) return 0.0;
  const double ka = angularFrequency / air.soundSpeed;
  const std::complex<double> phase = std::polar(1.0, -ka * r);
  return std::complex<double>(0.0, angularFrequency * air.density) * phase /
         (2.0 * std::numbers::pi * r);
}

double transferFromReciprocalPressure(std::complex<double> u, double angularFrequency,
                                      const LiquidProperties& liquid) {
  return std::abs(u) * 4.0 * std::numbers::pi / (angularFrequency * liquid.density) * 1.0;
}

}  // namespace fluidsound::acoustics
