// acoustics/analysis/validation.h — the analytic bubble-acoustics check behind `fluidsound validate`:
// single bubbles rendered by the real synthesizer, measured (tone_analysis.h) and compared with
// the model's formulas and the published tables of docs/physics.md §9.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "acoustics/synthesis/synthesizer.h"

namespace fluidsound::acoustics {

/// One line of the validation table.
struct ValidationRow {
  std::string check;      ///< what is measured, e.g. "frequency R=1 mm"
  std::string reference;  ///< what it is compared with, e.g. "model f_d" or "T1 (physics.md)"
  double measured = 0.0;
  double expected = 0.0;
  double tolerance = 0.0; ///< allowed |measured − expected| / |expected|, or absolute if `absolute`
  bool absolute = false;
  std::string unit;       ///< unit of measured and expected
  bool pass = false;
  std::string note;       ///< why `measured` is not a number (e.g. the bubble was dropped), if so
};

/// @brief Renders one bubble born at t = 0 through synthesize() and returns its pressure [Pa].
/// @param depth     constant depth below a free surface [m]; none = deep (no track)
/// @param transfer  constant transfer to the single listener
std::vector<float> renderSingleBubble(double radius, std::optional<double> depth, double transfer,
                                      const SynthesisSettings& settings);

/// @brief Least-squares amplitude A [Pa] of x ≈ A e^{−βt} sin(2π f t) (t from the first sample).
double fitDampedSineAmplitude(const std::vector<float>& x, double sampleRate, double frequency,
                              double decayRate);

/// @brief Every check of the validation matrix that applies to settings.model: frequency and
///        decay of deep bubbles (0.25–5 mm), free-surface shift at h = 1.5, 2, 5 R, the −90 dB
///        cut-off, linearity, the Nyquist guard, excitation amplitude and the chirp. With the
///        chirp on, the checks whose estimators assume a steady pitch (deep bubbles, depth shift)
///        render with it off and say so ("(chirp off)"). A signal an estimator cannot measure
///        (e.g. a bubble dropped above Nyquist) gives a failed row with a `note`, never an
///        exception.
std::vector<ValidationRow> validateBubbleAcoustics(const SynthesisSettings& settings,
                                                   const ProgressCallback& progress = {});

}  // namespace fluidsound::acoustics
