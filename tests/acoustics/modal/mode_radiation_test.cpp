// tests/acoustics/modal/mode_radiation_test.cpp — a mode's monopole and dipole from the voxel
// surface, and the pressure they give, against the divergence theorem and the compact sphere's
// analytic fields (docs/solids.md, Radiation).
#include "acoustics/modal/mode_radiation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

namespace fluidsound::acoustics {
namespace {

constexpr double kPi = std::numbers::pi;

/// The model of a voxel solid whose single "mode" at f [Hz] moves every surface node by shape(x).
ModalModel withShape(const VoxelSolid& solid, double f, const auto& shape) {
  ModalModel model;
  setModelSurface(model, solid, hexMesh(solid));
  model.surfaceShapes.resize(3 * static_cast<Eigen::Index>(model.surfaceNodes.size()), 1);
  for (std::size_t s = 0; s < model.surfaceNodes.size(); ++s) {
    const Eigen::Vector3d u = shape(model.surfacePositions[s]);
    for (int c = 0; c < 3; ++c) model.surfaceShapes(3 * static_cast<Eigen::Index>(s) + c, 0) = static_cast<float>(u[c]);
  }
  model.frequency = {f};
  model.decayRate = {0.0};
  model.dampedFrequency = {f};
  return model;
}

// The divergence theorem on the voxel surface: a translation u = x̂ displaces no volume and has the
// dipole (3/2)·V·x̂ (∮ x n_x dS = V); a uniform expansion u = x − c displaces ∮ (x − c)·n dS = 3V.
// Exact on the voxel surface (its faces are flat and the shapes linear), so to float rounding.
TEST(ModeRadiation, MultipolesFollowTheDivergenceTheorem) {
  const VoxelSolid box = voxelBox({0.04, 0.02, 0.03}, 0.01);
  const double volume = 0.04 * 0.02 * 0.03;
  const ModeMultipoles translation = modeMultipoles(withShape(box, 500.0, [](const Eigen::Vector3d&) {
    return Eigen::Vector3d(1.0, 0.0, 0.0);
  }));
  EXPECT_NEAR(translation.centre.x(), 0.02, 1e-9);
  EXPECT_NEAR(translation.monopole[0], 0.0, 1e-9 * volume);
  EXPECT_NEAR(translation.dipole[0].x(), 1.5 * volume, 1e-6 * volume);
  EXPECT_NEAR(translation.dipole[0].y(), 0.0, 1e-9 * volume);
  const Eigen::Vector3d centre(0.02, 0.01, 0.015);
  const ModeMultipoles expansion =
      modeMultipoles(withShape(box, 500.0, [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(x - centre); }));
  EXPECT_NEAR(expansion.monopole[0], 3.0 * volume, 1e-6 * volume);
}

// The fields. A compact pulsating body of volume change Q·q: p = −ρ₀ω²Q q/(4πr), the same in every
// direction. A compact sphere (radius a) oscillating along x with displacement amplitude X:
// p = ρ₀ω²a³X cos θ/(2r)·(ik + 1/r) in magnitude √(k² + 1/r²)·ρ₀ω²a³X cos θ/(2r) (Lamb §295's
// far field ρ₀ω²a³U cos θ/(2rc) with its near-field term), zero at 90°. A voxel sphere (a = 5 cm,
// 5 mm voxels) holds its volume within 1 %, so 2 % for the dipole's magnitude; the 1/r law exactly.
TEST(ModeRadiation, PressureOfAPulsatingAndAnOscillatingBody) {
  const AirProperties air;
  const double f = 200.0, omega = 2.0 * kPi * f, k = omega / air.soundSpeed, a = 0.05;
  const VoxelSolid sphere = voxelSolidFromInside([&](const Eigen::Vector3d& x) { return x.norm() < a; },
                                                 Eigen::Vector3d::Constant(-a), Eigen::Vector3d::Constant(a), 0.005);
  const ModalModel oscillating = withShape(sphere, f, [](const Eigen::Vector3d&) { return Eigen::Vector3d(1.0, 0.0, 0.0); });
  const ModeMultipoles dipole = modeMultipoles(oscillating);
  for (double r : {0.5, 2.0}) {
    const double onAxis = std::abs(radiationGains(oscillating, dipole, dipole.centre + Eigen::Vector3d(r, 0, 0), air)[0]);
    const double expected = std::hypot(k, 1.0 / r) * air.density * omega * omega * a * a * a / (2.0 * r);
    EXPECT_NEAR(onAxis, expected, 0.02 * expected) << r;
    EXPECT_NEAR(std::abs(radiationGains(oscillating, dipole, dipole.centre + Eigen::Vector3d(0, r, 0), air)[0]), 0.0,
                1e-6 * expected);
  }
  const ModalModel pulsating = withShape(sphere, f, [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(x - Eigen::Vector3d::Zero()); });
  const ModeMultipoles monopole = modeMultipoles(pulsating);
  const double near = std::abs(radiationGains(pulsating, monopole, monopole.centre + Eigen::Vector3d(0, 0, 1.0), air)[0]);
  const double far = std::abs(radiationGains(pulsating, monopole, monopole.centre + Eigen::Vector3d(0, 3.0, 0), air)[0]);
  EXPECT_NEAR(near, air.density * omega * omega * monopole.monopole[0] / (4.0 * kPi * 1.0), 1e-9 * near);
  EXPECT_NEAR(far * 3.0, near, 1e-9 * near);
  EXPECT_NEAR(radiationDelay(monopole, monopole.centre + Eigen::Vector3d(0, 3.0, 0), air), 3.0 / air.soundSpeed, 1e-12);
}

TEST(ModeRadiation, RefusesAListenerAtTheCentre) {
  const ModalModel model = withShape(voxelBox({0.02, 0.02, 0.02}, 0.01), 100.0, [](const Eigen::Vector3d&) {
    return Eigen::Vector3d(0.0, 1.0, 0.0);
  });
  const ModeMultipoles multipoles = modeMultipoles(model);
  EXPECT_THROW(radiationGains(model, multipoles, multipoles.centre, AirProperties{}), std::invalid_argument);
}

}  // namespace
}  // namespace fluidsound::acoustics

namespace fluidsound::acoustics {
namespace {

// Beyond the compact limit each face the listener sees radiates as a baffled piston (Rayleigh's
// integral): a 20 × 20 cm plate, 1 cm thick, moving along y at 20 kHz (ka = 52) as a rigid piston
// of displacement X gives on its axis, far away (50 m: the plate's Rayleigh distance is 0.5 m and
// the path differences across it 1e-4 m, 0.04 rad), ρ₀ω²·A·X/(2πr) with A its top face's area
// (Kinsler, Frey et al., Fundamentals of Acoustics, §7.4): the bottom face, turned away, is not
// heard. Tolerance 0.1 %: the residual phase across the face (1 − cos 0.04 rad).
TEST(ModeRadiation, BeyondTheCompactLimitFacesRadiateAsBaffledPistons) {
  const AirProperties air;
  const double f = 20000.0, omega = 2.0 * kPi * f, r = 50.0;
  VoxelSolid plate = voxelBox({0.2, 0.01, 0.2}, 0.01);
  plate.origin = {-0.1, -0.005, -0.1};
  const ModalModel piston = withShape(plate, f, [](const Eigen::Vector3d&) { return Eigen::Vector3d(0.0, 1.0, 0.0); });
  const ModeMultipoles faces = modeMultipoles(piston);
  EXPECT_GT(omega / air.soundSpeed * faces.radius, 2.0);
  const double above = std::abs(radiationGains(piston, faces, Eigen::Vector3d(0, r, 0), air)[0]);
  const double expected = air.density * omega * omega * 0.04 / (2.0 * kPi * r);
  EXPECT_NEAR(above, expected, 1e-3 * expected);
  EXPECT_DOUBLE_EQ(radiationBlend(0.5), 0.0);
  EXPECT_DOUBLE_EQ(radiationBlend(1.0), 0.5);
  EXPECT_DOUBLE_EQ(radiationBlend(2.0), 1.0);
}

}  // namespace
}  // namespace fluidsound::acoustics
