// acoustics/analysis/centroid_prediction.h — the spectrum a render of bubble tracks should have, predicted
// from the tracks alone: each bubble's radiated energy at each listener placed at its ringing
// frequency; its spectral centroid is the reference of issue 6's end-to-end check
// (docs/synthesis.md, "What the spectrum shows").
#pragma once

#include <cstdint>
#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/analysis/spectrum_statistics.h"
#include "acoustics/synthesis/synthesizer.h"

namespace fluidsound::acoustics {

/// The predicted spectrum of one listener's channel, summarised.
struct PredictedSpectrum {
  double centroid = 0.0;  ///< Σ f·E / Σ E over the band [Hz]; 0 if no energy falls in the band
  double bandEnergy = 0.0;  ///< Σ E over the band: ∫ p² dt of the channel within the band [Pa²·s]
  std::int64_t bubbles = 0;  ///< bubbles that contributed (rendered, born before the clip's end)
};

/// @brief Predicted band energy and spectral centroid of each listener's channel of
///        synthesize(tracks, settings), from the tracks and the synthesizer's own oscillator
///        definitions (instantaneous_frequency.h), without rendering.
///
/// Each bubble b ringing p_b(t) = A e^{−βτ} sin φ(t), τ = t − t_b, heard through g_b,l(t), radiates
/// at listener l the energy ∫ g² p² dt = ∫ g(t)² A² e^{−2βτ} sin²φ dτ. Over each short stretch of
/// its life it is taken as the rendered damped sine e^{−βτ} sin(ω_d τ) with the instantaneous
/// ω_d = ω(t) (instantaneous_frequency.h), whose band energy E_line and centroid f_line come from
/// its sampled spectrum (damped_sine_spectrum.h; E_line ≈ ω_d²/(4βω₀²) over all frequencies, the
/// whole energy of a unit damped sine). The channel's prediction over `band` is
///     E = Σ_b Σ_j A² g(t_j)² E_line(ω_d(t_j)) U_b/N,    centroid = Σ_b Σ_j (same) f_line(t_j) / E,
/// t_j the midpoints of N equal steps in u = 1 − e^{−2β(t−t_b)} over [0, U_b] (each carries an
/// equal share of the decay's energy; exact for constant g and ω_d), U_b = 1 − e^{−2βT_b} the
/// share before the cut, T_b = min(cut-off time, clip end − t_b); depth and transfer come from the
/// same monotone-cubic track interpolant as the synthesizer's.
/// The line is not a Lorentzian about ω_d: its tail tends to a constant below the line and falls
/// as ω⁻⁴ above it, so f_line lies below ω_d/2π (by 1.1 % for R = 1 mm in 20 Hz … 20 kHz at 48 kHz).
///
/// **Included**, as the synthesizer renders them: amplitude A (file or excitation model), decay β,
/// the deep Minnaert frequency with the Strasberg depth shift along the track (and the hydrostatic
/// factor and chirp when the model enables them), the damped ringing frequency √(ω² − β²), the
/// sine onset's spectrum, the transfer to each listener along the track, the cut-off at
/// `settings.cutoffDecibels` and the end of the clip (`settings.duration`; no end without one),
/// the Nyquist guard (a bubble the synthesizer drops contributes nothing), sampling (the line's
/// images every fs).
/// **Neglected**: interference between bubbles (cross terms ∫ p_a p_b average out for incoherent
/// births; they are the prediction's scatter, not a bias); the spectral spread from a frequency or
/// transfer that changes within a line's decay (each stretch keeps its own line); the truncation
/// of a line by the clip's end or the cut-off (its energy is cut, its shape kept); a birth between
/// two samples (the first sample's phase, under one sample); the spectral estimator's window (a
/// symmetric kernel: it moves a centroid only through the band edges).
/// @param band  where the centroid is taken [Hz]
std::vector<PredictedSpectrum> predictedSpectra(const BubbleTrackSet& tracks,
                                                const SynthesisSettings& settings,
                                                const FrequencyBand& band);

}  // namespace fluidsound::acoustics
