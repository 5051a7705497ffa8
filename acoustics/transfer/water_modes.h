// acoustics/transfer/water_modes.h — the lowest acoustic eigenmodes of one frame's water: the
// resonances of the water side's operator K(ω) = L − k_w² M (water_helmholtz.h), L φ = λ M φ
// with λ = k² [1/m²] and φᵀMφ = 1, so that K⁻¹ = Σ_j φ_j φ_jᵀ / (λ_j − k_w²) over all modes.
// The geometric transfer takes the modes below a cut out of its band interpolation and adds them
// back in closed form at each sample's own frequency (docs/transfer.md, "Bands and routes").
// Shift-invert Lanczos (Spectra, Debian libspectra-dev, MPL-2.0) on M^{-1/2} L M^{-1/2}.
#pragma once

#include <Eigen/Core>

namespace fluidsound::acoustics {

class WaterHelmholtz;

/// The modes of a frame's water below a wavenumber cut, lowest first.
struct WaterModes {
  Eigen::VectorXd eigenvalue;  ///< λ_j = k_j² [1/m²], ascending, each < the cut
  Eigen::MatrixXd shape;       ///< unknowns × modes, M-orthonormal columns (φᵀMφ = 1)
  bool complete = true;        ///< false when more than the allowed count lie below the cut
  int operations = 0;          ///< shift-invert solves the Lanczos iteration took
};

/// @brief Every mode of `water` with λ < maxEigenvalue [1/m²], by shift-invert Lanczos about a
///        shift just below 0 (the operator is positive definite wherever the liquid meets air;
///        the shift keeps a liquid shut in by solids from making it singular). Deterministic.
/// @param maxModes  at most this many are sought; beyond it the result is marked incomplete
/// @throws std::runtime_error when the Lanczos iteration does not converge
WaterModes lowestWaterModes(const WaterHelmholtz& water, double maxEigenvalue, int maxModes);

/// The same modes by a dense generalised eigensolver (Eigen): the reference for small frames.
WaterModes lowestWaterModesDense(const WaterHelmholtz& water, double maxEigenvalue);

}  // namespace fluidsound::acoustics
