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
// added-mass tensors differ). Not modelled: radiation beyond the compact limit (ka ≳ 1, where a
// high mode's cells radiate on their own and this sum underestimates it) and occlusion.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/modal/modal_analysis.h"

namespace fluidsound::acoustics {

/// Each mode's multipoles about the body's surface centroid.
struct ModeMultipoles {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< c: the surface's area centroid [m]
  std::vector<double> monopole;                       ///< Q_j [m²/√kg]: volume per unit modal displacement
  std::vector<Eigen::Vector3d> dipole;                ///< D_j [m³/√kg], with the factor 3/2
};

/// @brief The monopole and dipole of each mode of `model` from its surface faces (each face's
///        normal displacement the mean of its four corners', at its centre).
ModeMultipoles modeMultipoles(const ModalModel& model);

/// @brief Per mode, the complex gain g_j from its state to the pressure [Pa] at `listener` [m]:
///        with q_j = Im z_j and z_j ∝ e^{s_j t}, s_j = −d_j + iω_d,j, the pressure is Im(g_j·z_j),
///        g_j = ρ₀/(4πr)·s_j²·[Q_j + (r̂·D_j)(s_j/c + 1/r)] (time derivatives exact for the
///        damped mode). For synthesizeModalImpacts (modal_synthesis.h) with the delay below.
/// @throws std::invalid_argument if the listener is at the centre
std::vector<std::complex<double>> radiationGains(const ModalModel& model, const ModeMultipoles& multipoles,
                                                 const Eigen::Vector3d& listener, const AirProperties& air);

/// @brief The delay r/c [s] from the body's centre to `listener`.
double radiationDelay(const ModeMultipoles& multipoles, const Eigen::Vector3d& listener, const AirProperties& air);

}  // namespace fluidsound::acoustics
