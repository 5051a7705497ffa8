// acoustics/modal/modal_synthesis.h — the sound of a body's modes struck by impacts: each mode a
// damped oscillator advanced by the exact recurrence z ← z·e^{(−d + iω_d)Δt} that the bubbles use
// (oscillator_bank.h), each impact adding its impulse response at its exact (sub-sample) time
// (docs/solids.md, Synthesis).
//
// A mode j of M-orthonormal shape φ_j obeys q̈ + 2d_j q̇ + ω_j² q = φ_jᵀf (shared solids.md §1.1–1.2).
// An impulse J at a surface point gives it the modal impulse J_j = φ_j(x)·J, and its response is
//   q_j(t) = (J_j/ω_d,j)·e^{−d_j t}·sin(ω_d,j t),   ω_d,j = √(ω_j² − d_j²),
// the initial modal velocity exactly J_j: the lecture's slide has 2Δt·g/|Im ω| there, twice this
// (its c₁ − c₂ counts both exponentials; solids.md §1.1 "Caution"). A Hertz impact of duration t_c
// is taken as a half-sine force pulse: the same response delayed by t_c/2 and scaled by
// halfSinePulseFactor(ω_j, t_c) (hertz_contact.h).
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "acoustics/modal/modal_analysis.h"
#include "acoustics/modal/mode_compression.h"

namespace fluidsound::acoustics {

/// One impact on a body.
struct ModalImpact {
  double time = 0.0;                                   ///< first touch [s]
  std::size_t surfaceNode = 0;                         ///< where: index into ModalModel::surfaceNodes
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();  ///< J on the body [N·s], in the body's (model's) frame
  double contactDuration = 0.0;                        ///< t_c [s]; 0: an ideal impulse
};

/// @brief The modal impulses J_j = φ_j(x)·J [√kg·m/s] an impact gives each mode of `model`.
Eigen::VectorXd modalImpulses(const ModalModel& model, const ModalImpact& impact);

/// @brief The displacement q_j(t) [√kg·m] of mode j after the impact (0 before it): the corrected
///        impulse response, delayed by t_c/2 and scaled by the half-sine pulse's factor.
double modalDisplacement(const ModalModel& model, std::size_t mode, const ModalImpact& impact, double time);

struct ModalSynthesisSettings {
  double sampleRate = 48000.0;  ///< [Hz]
  /// Per event (the thesis's 1e-5, §3.52, made relative to the event): an impact does not excite
  /// an oscillator whose amplitude through its gain is below this fraction of the event's loudest,
  /// and an oscillator falls silent once below this fraction of the loudest event that excited
  /// it; 0 keeps every mode to the end.
  double truncation = 1e-5;
  /// Modes grouped by groupIndistinguishableModes (mode_compression.h): each group one oscillator
  /// at its lead's frequency and decay. An impact gives group g the complex amplitude of magnitude
  /// √(Σ_j |g_j·a_j|²) and the phase of Σ_j g_j·a_j (a_j the members' amplitudes, g_j their
  /// gains): the members' energy over times longer than their beating, which is what separate
  /// modes closer than the ear's discrimination sound like. Null: every mode its own oscillator.
  const ModeGroups* compression = nullptr;
};

/// What a synthesis did.
struct ModalSynthesisStatistics {
  std::size_t oscillatorSamples = 0;  ///< mode-samples advanced (the cost)
  std::size_t modesTruncated = 0;     ///< times a mode fell below the truncation floor and stopped
  std::size_t modesSkipped = 0;       ///< times an impact left a mode out: below the floor from the start
};

/// @brief `samples` samples of Σ_j Im(g_j·z_j), where q_j = Im z_j is mode j's displacement: the
///        modes' sum through complex gains g_j (per unit modal displacement: a real gain weights
///        q_j, an imaginary one its quadrature, as a radiation filter's phase does), for impacts in
///        any order.
/// @param gains  one per mode of `model`
/// @param delay  added to every impact's time [s] (a listener's r/c), ≥ 0
/// @note Deterministic; exact at the samples up to rounding (complex doubles).
std::vector<float> synthesizeModalImpacts(const ModalModel& model, std::span<const ModalImpact> impacts,
                                          std::span<const std::complex<double>> gains, std::size_t samples,
                                          double delay, const ModalSynthesisSettings& settings,
                                          ModalSynthesisStatistics* statistics = nullptr);

/// A force applied at a surface node, sample by sample (a rubbing contact: surface_roughness.h).
struct ModalForce {
  double startTime = 0.0;                   ///< time of the first sample [s]
  std::span<const Eigen::Vector3f> force;   ///< [N] on the body, its frame, one per sample
  /// where, sample by sample: indices into ModalModel::surfaceNodes, as many as `force`, or one
  /// for all (a contact that stays put)
  std::span<const std::size_t> surfaceNodes;
};

/// @brief `samples` samples of Σ_j Im(g_j·z_j) driven by forces held constant over each sample (all
///        forces summed per mode, one pass per mode):
///        z ← r·z + g·(r − 1)/(s·ω_d), g = φ_j(x)·F, the exact response of the damped mode to a
///        piecewise-constant force (q = Im z; a constant g settles at g/ω², the static
///        deflection). The same modes, gains and delay as synthesizeModalImpacts; a force's
///        samples start at the output sample nearest its startTime + delay. After its last driven
///        sample a mode rings until |z| falls below settings.truncation of its largest |z| while
///        driven (0: to the end); compression is not applied to forces.
std::vector<float> synthesizeModalForces(const ModalModel& model, std::span<const ModalForce> forces,
                                         std::span<const std::complex<double>> gains, std::size_t samples,
                                         double delay, const ModalSynthesisSettings& settings);

}  // namespace fluidsound::acoustics
