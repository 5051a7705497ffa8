// acoustics/modal/mode_radiation.cpp — see mode_radiation.h.
#include "acoustics/modal/mode_radiation.h"

#include <algorithm>
#include <cmath>
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
  out.faceArea = area;
  out.faceDisplacement.resize(static_cast<Eigen::Index>(model.surfaceFaces.size()), static_cast<Eigen::Index>(modes));
  for (std::size_t f = 0; f < model.surfaceFaces.size(); ++f) {
    const SurfaceFace& face = model.surfaceFaces[f];
    const Eigen::Vector3d centre = faceCentre(model, face);
    const Eigen::Vector3d arm = centre - out.centre;
    out.radius = std::max(out.radius, arm.norm());
    out.faceCentres.push_back(centre);
    out.faceNormals.push_back(face.side * Eigen::Vector3d::Unit(face.axis));
    for (std::size_t j = 0; j < modes; ++j) {
      double normal = 0.0;  // the face's mean normal displacement per unit q_j
      for (int node : face.nodes)
        normal += model.surfaceShapes(3 * node + face.axis, static_cast<Eigen::Index>(j));
      normal *= 0.25 * face.side;
      out.faceDisplacement(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(j)) = normal;
      out.monopole[j] += normal * area;
      out.dipole[j] += kDipoleFactor * normal * area * arm;
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
  // The faces the listener sees, with their distances.
  std::vector<std::size_t> seen;
  std::vector<double> faceDistance;
  for (std::size_t f = 0; f < multipoles.faceCentres.size(); ++f) {
    const Eigen::Vector3d toFace = listener - multipoles.faceCentres[f];
    if (toFace.dot(multipoles.faceNormals[f]) <= 0.0) continue;
    seen.push_back(f);
    faceDistance.push_back(toFace.norm());
  }
  std::vector<std::complex<double>> gains(model.frequency.size());
  for (std::size_t j = 0; j < gains.size(); ++j) {
    const std::complex<double> s(-model.decayRate[j], 2.0 * std::numbers::pi * model.dampedFrequency[j]);
    const double blend = radiationBlend(s.imag() / air.soundSpeed * multipoles.radius);
    std::complex<double> compact = 0.0, faces = 0.0;
    if (blend < 1.0)
      compact = spreading * s * s *
                (multipoles.monopole[j] + direction.dot(multipoles.dipole[j]) * (s / air.soundSpeed + 1.0 / r));
    if (blend > 0.0) {
      for (std::size_t i = 0; i < seen.size(); ++i)
        faces += multipoles.faceDisplacement(static_cast<Eigen::Index>(seen[i]), static_cast<Eigen::Index>(j)) *
                 std::exp(-s * (faceDistance[i] - r) / air.soundSpeed) / faceDistance[i];
      faces *= air.density * multipoles.faceArea / (2.0 * std::numbers::pi) * s * s;
    }
    gains[j] = (1.0 - blend) * compact + blend * faces;
  }
  return gains;
}

double radiationBlend(double ka) {
  if (!(ka > 0.5)) return 0.0;
  if (ka >= 2.0) return 1.0;
  const double x = 0.5 * (std::log2(ka) + 1.0);  // 0 at ka = 1/2, 1 at ka = 2
  return x * x * (3.0 - 2.0 * x);
}

double radiationDelay(const ModeMultipoles& multipoles, const Eigen::Vector3d& listener, const AirProperties& air) {
  return (listener - multipoles.centre).norm() / air.soundSpeed;
}

}  // namespace fluidsound::acoustics
