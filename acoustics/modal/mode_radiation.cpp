// acoustics/modal/mode_radiation.cpp — see mode_radiation.h.
#include "acoustics/modal/mode_radiation.h"

#include <numbers>
#include <stdexcept>

namespace fluidsound::acoustics {
namespace {

/// The flow's own dipole around a moving body, as a sphere's: its far field is 3/2 of the dipole
/// of the volume it displaces (Lamb §92).
constexpr double kDipoleFactor = 1.5;

Eigen::Vector3d faceCentre(const ModalModel& model, const SurfaceFace& face) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int node : face.nodes) sum += model.surfacePositions[static_cast<std::size_t>(node)];
  return 0.25 * sum;
}

}  // namespace

ModeMultipoles modeMultipoles(const ModalModel& model) {
  ModeMultipoles out;
  const double area = model.voxelSize * model.voxelSize;
  double totalArea = 0.0;
  for (const SurfaceFace& face : model.surfaceFaces) {
    out.centre += area * faceCentre(model, face);
    totalArea += area;
  }
  if (totalArea > 0.0) out.centre /= totalArea;
  const std::size_t modes = model.frequency.size();
  out.monopole.assign(modes, 0.0);
  out.dipole.assign(modes, Eigen::Vector3d::Zero());
  for (const SurfaceFace& face : model.surfaceFaces) {
    const Eigen::Vector3d arm = faceCentre(model, face) - out.centre;
    for (std::size_t j = 0; j < modes; ++j) {
      double normal = 0.0;  // the face's mean normal displacement per unit q_j
      for (int node : face.nodes)
        normal += model.surfaceShapes(3 * node + face.axis, static_cast<Eigen::Index>(j));
      normal *= 0.25 * face.side * area;
      out.monopole[j] += normal;
      out.dipole[j] += kDipoleFactor * normal * arm;
    }
  }
  return out;
}

std::vector<std::complex<double>> radiationGains(const ModalModel& model, const ModeMultipoles& multipoles,
                                                 const Eigen::Vector3d& listener, const AirProperties& air) {
  const Eigen::Vector3d toListener = listener - multipoles.centre;
  const double r = toListener.norm();
  if (!(r > 0.0)) throw std::invalid_argument("radiationGains: the listener is at the body's centre");
  const Eigen::Vector3d direction = toListener / r;
  const double spreading = air.density / (4.0 * std::numbers::pi * r);
  std::vector<std::complex<double>> gains(model.frequency.size());
  for (std::size_t j = 0; j < gains.size(); ++j) {
    const std::complex<double> s(-model.decayRate[j], 2.0 * std::numbers::pi * model.dampedFrequency[j]);
    gains[j] = spreading * s * s *
               (multipoles.monopole[j] + direction.dot(multipoles.dipole[j]) * (s / air.soundSpeed + 1.0 / r));
  }
  return gains;
}

double radiationDelay(const ModeMultipoles& multipoles, const Eigen::Vector3d& listener, const AirProperties& air) {
  return (listener - multipoles.centre).norm() / air.soundSpeed;
}

}  // namespace fluidsound::acoustics
