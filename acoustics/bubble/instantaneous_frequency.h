// acoustics/bubble/instantaneous_frequency.h — the angular frequency at which the synthesizer rings a
// bubble at each instant (deep Minnaert ω₀, Strasberg depth shift, optional hydrostatic factor and
// chirp, damped): one definition shared by the synthesizer and by what predicts its output
// (centroid_prediction.h). docs/synthesis.md, "What is rendered".
#pragma once

#include "acoustics/bubble/bubble_oscillator.h"
#include "acoustics/bubble/bubble_track.h"
#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/bubble/oscillator_model.h"

namespace fluidsound::acoustics {

/// The constants that fix how one bubble rings.
struct RingingBubble {
  double radius = 0.0;       ///< R [m]
  double birth = 0.0;        ///< t_b [s]
  OscillatorConstants deep;  ///< deep, at the surface's ambient pressure p₀
  /// ω₀ of the adiabatic model at p₀ [rad/s], the reference of the hydrostatic factor
  double adiabaticAngularFrequency = 0.0;
};

/// @brief The ringing constants of `bubble` (its radius, birth and optional amplitude) under
///        `model` (bubble_oscillator.h for ω₀, β and A).
RingingBubble ringingBubble(const BubbleTrack& bubble, const LiquidProperties& liquid,
                            const OscillatorModel& model);

/// @brief Instantaneous damped angular frequency [rad/s] of a ringing bubble:
///        ω(t) = √((ω₀ · S(h) · H(h) · C(t))² − β²), S the Strasberg free-surface factor
///        (depth_shift.h, physics.md §5), H the hydrostatic factor (model.hydrostatic), C the van
///        den Doel chirp 1 + ξβ(t − t_b) (model.chirp, physics.md §7.4); 0 if β ≥ the undamped
///        value.
/// @param depth  h [m] from the bubble centre to the free surface; +∞ for a deep bubble (S = H = 1)
/// @param time   t [s], for the chirp
double instantaneousAngularFrequency(const RingingBubble& bubble, double depth, double time,
                                     const LiquidProperties& liquid, const OscillatorModel& model);

/// @brief Highest instantaneous angular frequency [rad/s] the bubble reaches while it rings down
///        by `cutoffDecibels`: at its shallowest track sample (the track interpolant is monotone
///        between samples) and, with the chirp, at the cut-off time. The synthesizer drops a bubble
///        whose peak reaches the Nyquist frequency.
double peakAngularFrequency(const RingingBubble& ringing, const BubbleTrack& bubble,
                            double cutoffDecibels, const LiquidProperties& liquid,
                            const OscillatorModel& model);

}  // namespace fluidsound::acoustics
