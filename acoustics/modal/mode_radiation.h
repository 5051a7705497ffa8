// acoustics/modal/mode_radiation.h — how each mode of a body sounds at a listener: the body as a
// compact source, its mode's monopole and dipole, with the 1/r spreading, the dipole's near field
// and the delay r/c (docs/solids.md, Radiation; shared solids.md §5 "Compact-source multipoles").
//
// A mode j moving the surface by u = φ_j·q_j displaces the air with the volume Q_j·q_j,
// Q_j = ∮ φ_j·n dS, and the dipole moment D_j·q_j, D_j = (3/2)·∮ (x − c)(φ_j·n) dS about the
// surface's centroid c. For ka ≪ 1 (a the body's size) the pressure at distance r, direction r̂ is
//   p = ρ₀/(4πr) · [ Q_j·q̈_j + (r̂·D_j)·(q⃛_j/c + q̈_j/r) ](t − r/c)
// (a monopole, and a dipole with its 1/r² near field). The factor 3/2 is the flow's own dipole
// around a moving body, exact for a sphere (an oscillating rigid sphere's far field is
// ρ₀ω²a³U cos θ/(2rc); Lamb, Hydrodynamics §92 and §295), approximate for other shapes (their
// added-mass tensors differ).
//
// Beyond the compact limit the multipoles fail, and for a free body they fail early: an elastic
// mode is orthogonal to the rigid translations (∫ρφ_j dV = 0), so a thin plate's bending modes
// displace almost no net volume and almost no dipole — a free 20 × 20 × 1 cm steel plate struck
// at 1 m/s gave 2e-8 Pa at 2 m (its lowest mode at ka ≈ 2.6: not compact at all). There the
// surface radiates face by face: each face f that the listener sees (its outward normal towards
// the listener) as a baffled piston, the Rayleigh integral's ρ₀·A_f·ü_n/(2π r_f) with its own delay
// r_f/c (Kinsler, Frey et al., Fundamentals of Acoustics, §7.4). The gain is the multipoles'
// below ka = 1/2, the faces' above ka = 2, a smooth blend in log ka between (a choice: documented),
// with a the largest distance of a face from the centroid. Not modelled: a face hidden by another
// part of the body (only faces turned away are left out), diffraction, other bodies in the way.
#include <Eigen/Core>
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/modal/modal_analysis.h"

namespace fluidsound::acoustics {

/// Each mode's multipoles about the body's surface centroid, and its faces for the non-compact
/// regime.
struct ModeMultipoles {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< c: the surface's area centroid [m]
  std::vector<double> monopole;                       ///< Q_j [m²/√kg]: volume per unit modal displacement
  std::vector<Eigen::Vector3d> dipole;                ///< D_j [m³/√kg], with the factor 3/2
  double radius = 0.0;                                ///< a: the farthest face centre from c [m]
  std::vector<Eigen::Vector3d> faceCentres;           ///< [m]
  std::vector<Eigen::Vector3d> faceNormals;           ///< outward, unit
  double faceArea = 0.0;                              ///< h² [m²]
  /// faces × modes: face f's mean outward normal displacement per unit q_j [m/√kg]
  Eigen::MatrixXd faceDisplacement;
};

/// @brief The monopole and dipole of each mode of `model` from its surface faces (each face's
///        normal displacement the mean of its four corners', at its centre).
ModeMultipoles modeMultipoles(const ModalModel& model);

/// @brief Per mode, the complex gain g_j from its state to the pressure [Pa] at `listener` [m]:
///        with q_j = Im z_j and z_j ∝ e^{s_j t}, s_j = −d_j + iω_d,j, the pressure is Im(g_j·z_j),
///        g_j = ρ₀/(4πr)·s_j²·[Q_j + (r̂·D_j)(s_j/c + 1/r)] (time derivatives exact for the
///        damped mode) for ka ≤ 1/2, and Σ_f ρ₀·s_j²·A·u_fj·e^{−s_j(r_f − r)/c}/(2π r_f) over the
///        faces turned towards the listener for ka ≥ 2 (k = ω_d,j/c), blended in log ka between
///        (radiationBlend). For synthesizeModalImpacts (modal_synthesis.h) with the delay below.
/// @throws std::invalid_argument if the listener is at the centre
std::vector<std::complex<double>> radiationGains(const ModalModel& model, const ModeMultipoles& multipoles,
                                                 const Eigen::Vector3d& listener, const AirProperties& air);

/// @brief The share of the faces' gain at ka [-]: 0 up to ka = 1/2, 1 from ka = 2, a smoothstep in
///        log₂ ka between.
double radiationBlend(double ka);

/// @brief The delay r/c [s] from the body's centre to `listener`.
double radiationDelay(const ModeMultipoles& multipoles, const Eigen::Vector3d& listener, const AirProperties& air);

}  // namespace fluidsound::acoustics
