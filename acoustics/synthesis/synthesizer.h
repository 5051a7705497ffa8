// acoustics/synthesis/synthesizer.h — synthesis stage: the audio-rate sum over bubbles of transfer(t)·p(t),
// p a damped oscillator whose phase integrates its depth-shifted Minnaert frequency (Zheng & James
// 2009, "Harmonic Fluids"; docs/synthesis.md).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/synthesis/oscillator_kernel.h"
#include "acoustics/bubble/oscillator_model.h"

namespace fluidsound::acoustics {

/// Settings of one render; filled by tools/ from the command line and the bubble file.
struct SynthesisSettings {
  double sampleRate = 48000.0;      ///< Hz
  std::optional<double> duration;   ///< s; default: until the last bubble has decayed by cutoffDecibels
  double cutoffDecibels = 90.0;     ///< a bubble stops once it has decayed by this much [dB]
  LiquidProperties liquid;          ///< water at 20 °C
  OscillatorModel model;            ///< physics choices (docs/physics.md)
  /// Instruction-set version of the inner loop; default: the fastest this CPU runs. One the CPU
  /// cannot run is refused (std::invalid_argument) before any work.
  std::optional<OscillatorKernel> kernel;
};

/// What the render did, for the log and report.json.
struct SynthesisReport {
  std::int64_t oscillatorSamples = 0;   ///< Σ over rendered bubbles of samples from birth to the cut-off
  std::int64_t bubblesRendered = 0;
  std::int64_t bubblesAboveNyquist = 0; ///< dropped: highest frequency ≥ sampleRate/2 (would alias)
  std::int64_t bubblesSilent = 0;       ///< dropped: born after the end of the clip
  std::int64_t depthsClamped = 0;       ///< track samples shallower than 1.25 R (shift clamped)
  std::int64_t frames = 0;              ///< samples per channel
  double peakPascals = 0.0;             ///< largest |sample| over all channels [Pa]
  std::int64_t ringSamples = 0;         ///< resonator ring samples added (resonator_rings.h)
  OscillatorKernel kernel = OscillatorKernel::baseline;  ///< the inner loop that ran
};

/// The rendered sound: pressure [Pa] per listener, and the report.
struct SynthesisResult {
  std::vector<std::vector<float>> channels;
  SynthesisReport report;
};

/// Called now and then from the calling thread with the fraction done, 0 … 1.
using ProgressCallback = std::function<void(double fraction)>;

/// @brief The free-field pressure p(t) at 1 m of every bubble, weighted by its transfer to each
///        listener, summed: out_l(t) = Σ_b transfer_b,l(t) · p_b(t) [Pa].
///        p_b(t) = A e^{−β(t−t_b)} sin φ(t), φ(t_b) = 0, dφ/dt = ω₀·S(h(t))·H(h(t))·C(t), with S the
///        Strasberg free-surface factor, H the hydrostatic factor (option) and C the van den Doel
///        chirp (option). Depth and transfer are interpolated smoothly from the track samples.
/// @param tracks    validated bubble tracks (io/ validates files)
/// @param progress  optional; called from the calling thread
/// @throw std::invalid_argument if settings.kernel names a kernel this CPU cannot run
/// @note Parallel over time segments with TBB; bit-identical output for any thread count.
///       Memory: the output plus O(bubbles).
SynthesisResult synthesize(const BubbleTrackSet& tracks, const SynthesisSettings& settings,
                           const ProgressCallback& progress = {});

/// @brief Time after birth at which a bubble with decay rate β has decayed by `decibels`:
///        (decibels/20)·ln 10 / β [s] (docs/physics.md §1: 10.3616/β for 90 dB).
double decayTime(double decayRate, double decibels);

}  // namespace fluidsound::acoustics
