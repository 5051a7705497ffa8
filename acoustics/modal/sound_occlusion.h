// acoustics/modal/sound_occlusion.h — other bodies in the way between a sounding body and a
// listener: a body that the straight path crosses shadows it, by the barrier attenuation of
// Maekawa's chart, 10·log₁₀(3 + 20N) dB with the Fresnel number N = 2δ/λ, δ the detour of the
// sound over the obstacle (Maekawa 1968, "Noise reduction by screens", Applied Acoustics 1; the
// formula as Kurze & Anderson fitted it). The detour is taken around the obstacle's bounding
// sphere, and the attenuation capped at 24 dB, the chart's end (docs/solids.md, Radiation).
#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>

namespace fluidsound::acoustics {

/// A body that may stand between a sounding body and a listener.
struct Occluder {
  int body = -1;                                      ///< its index in the contact log
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< of its bounding sphere, world [m]
  double radius = 0.0;                                ///< of its bounding sphere [m]
  /// whether the segment between two world points [m] passes through the body
  std::function<bool(const Eigen::Vector3d&, const Eigen::Vector3d&)> crosses;
};

/// @brief The barrier attenuation [dB, ≥ 0] for a detour δ [m] at frequency f [Hz]:
///        10·log₁₀(3 + 20N), N = 2δf/c, from 4.8 dB at grazing (δ = 0) to at most 24 dB.
double barrierAttenuationDb(double detour, double frequency, double soundSpeed);

/// @brief The detour [m] of the path from `source` to `listener` over a sphere (centre, radius)
///        that stands between them: the path over the sphere's rim, perpendicular to the straight
///        line at the sphere's centre, less the straight path.
double detourOverSphere(const Eigen::Vector3d& source, const Eigen::Vector3d& listener,
                        const Eigen::Vector3d& centre, double radius);

/// @brief The amplitude factor [0, 1] per frequency (one per entry of `frequencies` [Hz]) of the
///        path from `source` to `listener`: the product of the barrier attenuations of every
///        occluder but `self` that the straight path crosses (1 when none does).
std::vector<double> occlusionFactors(const std::vector<Occluder>& occluders, int self, const Eigen::Vector3d& source,
                                     const Eigen::Vector3d& listener, const std::vector<double>& frequencies,
                                     double soundSpeed);

}  // namespace fluidsound::acoustics
