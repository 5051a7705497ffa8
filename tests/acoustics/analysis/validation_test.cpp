// Tests of acoustics/analysis/validation.h: `fluidsound validate` passes for the default model and for the
// documented options, and it can fail (a check that cannot fail is no check).
#include "acoustics/analysis/validation.h"

#include <gtest/gtest.h>

namespace fluidsound::acoustics {
namespace {

void expectAllPass(const SynthesisSettings& s) {
  const std::vector<ValidationRow> rows = validateBubbleAcoustics(s);
  EXPECT_GT(rows.size(), 30u);
  for (const ValidationRow& r : rows)
    EXPECT_TRUE(r.pass) << r.check << " vs " << r.reference << ": measured " << r.measured
                        << ", expected " << r.expected << " " << r.unit;
}

// Every row of physics.md §9 that applies to the default model, against the model and against
// the published tables T1, T2a, T3, T7 (tolerances in validation.cpp, each with its reason).
TEST(Validation, DefaultModelPassesEveryCheck) { expectAllPass(SynthesisSettings{}); }

// The thermal polytropic index model is checked against T1 "σ, κ_eff" and T2b "β Φ".
TEST(Validation, ThermalModelPassesEveryCheck) {
  SynthesisSettings s;
  s.model.polytropic = PolytropicModel::Thermal;
  expectAllPass(s);
}

// van den Doel's graphics damping against T2b's d column, at 44.1 kHz.
TEST(Validation, VanDenDoelDampingPassesEveryCheck) {
  SynthesisSettings s;
  s.sampleRate = 44100.0;
  s.model.damping = DampingModel::VanDenDoel;
  expectAllPass(s);
}

// With the chirp on (the van den Doel rise, ξ = 0.1), `validate` exited 5: the 0.25 mm bubble's
// chirped pitch reaches Nyquist before its cut-off, the synthesizer drops it and the FFT peak got
// no samples. The steady-pitch checks now render with the chirp off (and say so); every row passes.
TEST(Validation, ChirpModelPassesEveryCheck) {
  SynthesisSettings s;
  s.model.chirp = true;
  expectAllPass(s);
  int steady = 0;
  for (const ValidationRow& r : validateBubbleAcoustics(s))
    steady += r.check.find("(chirp off)") != std::string::npos ? 1 : 0;
  EXPECT_EQ(steady, 6 * 7 + 6) << "every deep-bubble row (7 per radius) and the 6 depth-shift rows";
}

// A render no estimator can measure fails its rows and says why, instead of throwing: at ξ = 5 a
// 1 mm bubble's pitch reaches f₀(1 + 5 ln 10^4.5) ≈ 53 f₀ = 174 kHz before its −90 dB cut-off, so
// the synthesizer drops it (the Nyquist guard) and the cut-off, linearity and chirp rows have
// nothing to measure.
TEST(Validation, AnUnmeasurableRenderFailsItsRowsWithAReason) {
  SynthesisSettings s;
  s.model.chirp = true;
  s.model.chirpRiseFactor = 5.0;
  int failed = 0;
  for (const ValidationRow& r : validateBubbleAcoustics(s)) {
    if (r.pass) continue;
    ++failed;
    EXPECT_NE(r.note.rfind("not measured: ", 0), std::string::npos) << r.check << ": " << r.note;
  }
  EXPECT_EQ(failed, 4) << "the cut-off, the two linearity rows and the chirp row";
}

// The table comparisons are live: a liquid 2 % denser than the tables' water moves every
// frequency by ≈ −1 %, beyond the 0.2 % tolerance, and the T1 rows must fail.
TEST(Validation, DetectsAWrongLiquid) {
  SynthesisSettings s;
  s.liquid.density *= 1.02;
  int failed = 0;
  for (const ValidationRow& r : validateBubbleAcoustics(s))
    if (r.reference.rfind("T1", 0) == 0) failed += r.pass ? 0 : 1;
  EXPECT_EQ(failed, 6);
}

}  // namespace
}  // namespace fluidsound::acoustics
