// acoustics/modal/sound_occlusion.cpp — see sound_occlusion.h.
#include "acoustics/modal/sound_occlusion.h"

#include <algorithm>
#include <cmath>

namespace fluidsound::acoustics {

namespace {
constexpr double kMaximumAttenuationDb = 24.0;  // the end of Maekawa's chart (N ≈ 12)
}  // namespace

double barrierAttenuationDb(double detour, double frequency, double soundSpeed) {
  const double fresnel = 2.0 * std::max(detour, 0.0) * frequency / soundSpeed;
  return std::min(10.0 * std::log10(3.0 + 20.0 * fresnel), kMaximumAttenuationDb);
}

double detourOverSphere(const Eigen::Vector3d& source, const Eigen::Vector3d& listener, const Eigen::Vector3d& centre,
                        double radius) {
  const Eigen::Vector3d line = listener - source;
  const double length = line.norm();
  if (!(length > 0.0)) return 0.0;
  const Eigen::Vector3d along = line / length;
  const double s = std::clamp((centre - source).dot(along), 0.0, length);  // the foot on the line
  const double offset = (source + s * along - centre).norm();              // the line's miss distance
  const double rise = std::max(radius - offset, 0.0);  // from the line to the rim on the line's side
  return std::hypot(s, rise) + std::hypot(length - s, rise) - length;
}

std::vector<double> occlusionFactors(const std::vector<Occluder>& occluders, int self, const Eigen::Vector3d& source,
                                     const Eigen::Vector3d& listener, const std::vector<double>& frequencies,
                                     double soundSpeed) {
  std::vector<double> factors(frequencies.size(), 1.0);
  for (const Occluder& o : occluders) {
    if (o.body == self || !o.crosses || !o.crosses(source, listener)) continue;
    const double detour = detourOverSphere(source, listener, o.centre, o.radius);
    for (std::size_t j = 0; j < frequencies.size(); ++j)
      factors[j] *= std::pow(10.0, -barrierAttenuationDb(detour, frequencies[j], soundSpeed) / 20.0);
  }
  return factors;
}

}  // namespace fluidsound::acoustics
