// acoustics/transfer/rigid_surface_air_field.cpp — see rigid_surface_air_field.h.
#include "acoustics/transfer/rigid_surface_air_field.h"

#include <cmath>
#include <numbers>

namespace fluidsound::acoustics {

std::complex<double> freeFieldAirPressure(const Vec3& point, const Vec3& source,
                                          double angularFrequency, const AirProperties& air) {
  const double r = std::hypot(point[0] - source[0], point[1] - source[1], point[2] - source[2]);
  if (r == 0.0) return 0.0;
  const double ka = angularFrequency / air.soundSpeed;
  const std::complex<double> phase = std::polar(1.0, -ka * r);
  return std::complex<double>(0.0, angularFrequency * air.density) * phase /
         (4.0 * std::numbers::pi * r);
}

std::complex<double> rigidSurfaceAirPressure(const Vec3& surfacePoint, const Vec3& listener,
                                             double angularFrequency, const AirProperties& air) {
  return 2.0 * freeFieldAirPressure(surfacePoint, listener, angularFrequency, air);
}

double transferFromReciprocalPressure(std::complex<double> u, double angularFrequency,
                                      const LiquidProperties& liquid) {
  return std::abs(u) * 4.0 * std::numbers::pi / (angularFrequency * liquid.density) * 1.0;
}

}  // namespace fluidsound::acoustics
