// acoustics/modal/hex_element.cpp — see hex_element.h.
#include "acoustics/modal/hex_element.h"

#include <bit>
#include <cmath>

#include <Eigen/Cholesky>

namespace fluidsound::acoustics {
namespace {

constexpr int kNodes = 8;
constexpr int kBubbles = 3;                  // (1 − ξ²), (1 − η²), (1 − ζ²)
constexpr int kCompatibleDofs = 3 * kNodes;  // 24
constexpr int kBubbleDofs = 3 * kBubbles;    // 9

/// Isotropic elasticity in Voigt order (xx, yy, zz, xy, yz, zx), engineering shear strains.
Eigen::Matrix<double, 6, 6> isotropicElasticity(double youngsModulus, double poissonsRatio) {
  const double lame = youngsModulus * poissonsRatio /
                      ((1.0 + poissonsRatio) * (1.0 - 2.0 * poissonsRatio));  // λ [Pa]
  const double shear = youngsModulus / (2.0 * (1.0 + poissonsRatio));         // μ [Pa]
  Eigen::Matrix<double, 6, 6> elasticity = Eigen::Matrix<double, 6, 6>::Zero();
  elasticity.topLeftCorner<3, 3>().setConstant(lame);
  elasticity.topLeftCorner<3, 3>().diagonal().array() += 2.0 * shear;
  elasticity.bottomRightCorner<3, 3>().diagonal().setConstant(shear);
  return elasticity;
}

/// The strain-displacement columns of one scalar field with physical gradient g [1/m], carried by
/// each of the three displacement components in turn.
Eigen::Matrix<double, 6, 3> strainColumns(const Eigen::Vector3d& g) {
  Eigen::Matrix<double, 6, 3> b;
  b << g.x(), 0.0, 0.0,   //
      0.0, g.y(), 0.0,    //
      0.0, 0.0, g.z(),    //
      g.y(), g.x(), 0.0,  //
      0.0, g.z(), g.y(),  //
      g.z(), 0.0, g.x();
  return b;
}

/// Natural coordinates (±1) of local node a = dx + 2·dy + 4·dz.
Eigen::Vector3d nodeNaturalCoordinates(int a) {
  return {(a & 1) ? 1.0 : -1.0, (a & 2) ? 1.0 : -1.0, (a & 4) ? 1.0 : -1.0};
}

}  // namespace

HexElementMatrix hexElementStiffness(double edge, double youngsModulus, double poissonsRatio) {
  const Eigen::Matrix<double, 6, 6> elasticity = isotropicElasticity(youngsModulus, poissonsRatio);
  const double naturalToPhysical = 2.0 / edge;       // dξ/dx [1/m]
  const double jacobian = edge * edge * edge / 8.0;  // det(dx/dξ) [m³]
  const double gaussPoint = 1.0 / std::sqrt(3.0);    // 2-point Gauss abscissa, weight 1
  Eigen::Matrix<double, kCompatibleDofs, kCompatibleDofs> kcc =
      Eigen::Matrix<double, kCompatibleDofs, kCompatibleDofs>::Zero();
  Eigen::Matrix<double, kCompatibleDofs, kBubbleDofs> kci =
      Eigen::Matrix<double, kCompatibleDofs, kBubbleDofs>::Zero();
  Eigen::Matrix<double, kBubbleDofs, kBubbleDofs> kii =
      Eigen::Matrix<double, kBubbleDofs, kBubbleDofs>::Zero();
  for (int q = 0; q < 8; ++q) {
    const Eigen::Vector3d xi = gaussPoint * nodeNaturalCoordinates(q);
    Eigen::Matrix<double, 6, kCompatibleDofs> compatible;
    for (int a = 0; a < kNodes; ++a) {
      const Eigen::Vector3d s = nodeNaturalCoordinates(a);
      const Eigen::Array3d factor = 1.0 + s.array() * xi.array();  // (1 + s_d ξ_d)
      const Eigen::Vector3d gradient =
          naturalToPhysical / 8.0 *
          Eigen::Vector3d(s.x() * factor.y() * factor.z(), s.y() * factor.x() * factor.z(),
                          s.z() * factor.x() * factor.y());
      compatible.middleCols<3>(3 * a) = strainColumns(gradient);
    }
    Eigen::Matrix<double, 6, kBubbleDofs> bubble;
    for (int m = 0; m < kBubbles; ++m) {
      Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
      gradient[m] = naturalToPhysical * (-2.0 * xi[m]);  // d(1 − ξ_m²)/dx_m
      bubble.middleCols<3>(3 * m) = strainColumns(gradient);
    }
    const Eigen::Matrix<double, 6, kCompatibleDofs> stressCompatible = elasticity * compatible;
    const Eigen::Matrix<double, 6, kBubbleDofs> stressBubble = elasticity * bubble;
    kcc.noalias() += jacobian * compatible.transpose() * stressCompatible;
    kci.noalias() += jacobian * compatible.transpose() * stressBubble;
    kii.noalias() += jacobian * bubble.transpose() * stressBubble;
  }
  // Static condensation: the bubble amplitudes minimise the energy for given node displacements.
  const Eigen::LLT<Eigen::Matrix<double, kBubbleDofs, kBubbleDofs>> bubbleFactor(kii);
  HexElementMatrix stiffness = kcc - kci * bubbleFactor.solve(kci.transpose());
  // Exact symmetry (the condensation's rounding is not quite symmetric).
  return 0.5 * (stiffness + stiffness.transpose()).eval();
}

HexElementMatrix hexElementMass(double edge, double density) {
  // ∫₀ʰ N N dx is h/3 for the same 1-D node and h/6 for the other; the 3-D integral is the product.
  const double elementMass = density * edge * edge * edge;  // ρh³ [kg]
  HexElementMatrix mass = HexElementMatrix::Zero();
  for (int a = 0; a < kNodes; ++a)
    for (int b = 0; b < kNodes; ++b) {
      const int differingAxes = std::popcount(static_cast<unsigned>(a ^ b));
      const double entry = elementMass / 27.0 / static_cast<double>(1 << differingAxes);
      for (int c = 0; c < 3; ++c) mass(3 * a + c, 3 * b + c) = entry;
    }
  return mass;
}

}  // namespace fluidsound::acoustics
