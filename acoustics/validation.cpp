// acoustics/validation.cpp — `fluidsound validate` checks (see validation.h; docs/physics.md §9).
#include "acoustics/validation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "acoustics/bubble_oscillator.h"
#include "acoustics/depth_shift.h"
#include "acoustics/oscillator_bank.h"
#include "acoustics/tone_analysis.h"

namespace fluidsound::acoustics {
namespace {

/// Reference rows of shared physics.md (water at 20 °C, default constants): T1 natural frequency
/// [Hz] "σ, κ=γ" and "σ, κ_eff (Φ)"; T2a Devin β [1/s]; T2b "β Φ" and van den Doel d [1/s];
/// T7 jet p(1 m) [Pa]. Published tables, not our own output.
struct ReferenceBubble {
  double radius;         // m
  double fAdiabatic;     // T1 σ, κ=γ
  double fThermal;       // T1 σ, κ_eff
  double betaDevin;      // T2a
  double betaThermal;    // T2b β Φ
  double vanDenDoel;     // T2b d
  double jetPressure;    // T7 jet p(1 m)
};
constexpr std::array<ReferenceBubble, 6> kReference{{
    {0.25e-3, 13174.9, 12811.0, 2551.6, 2491.8, 2341.5, 0.6575},
    {0.5e-3, 6580.3, 6451.8, 1014.2, 995.7, 904.0, 0.6552},
    {1e-3, 3288.3, 3243.0, 407.85, 402.05, 357.68, 0.6541},
    {2e-3, 1643.7, 1627.7, 167.08, 165.22, 145.50, 0.6535},
    {4e-3, 821.7, 816.1, 70.07, 69.46, 60.96, 0.4964},
    {5e-3, 657.4, 653.3, 53.26, 52.83, 46.36, 0.2709},
}};

// Tolerances of the validation matrix (physics.md §9), each with its reason.
constexpr double kFrequencyTolerance = 0.002;  // #1: estimator ≤ 0.002 %, ω_d vs ω₀ ≤ 0.05 %
constexpr double kDecayTolerance = 0.01;       // #2: robust estimator ≤ 0.25 %
constexpr double kShiftTolerance = 0.001;      // #5: ratio of two FFT peaks, ≤ 0.002 % each
constexpr double kLinearityTolerance = 1e-6;   // #10: float rounding only
constexpr double kAmplitudeTolerance = 0.001;  // #12: formula identity
constexpr double kChirpTolerance = 0.01;       // #13: zero-crossing period ≈ 0.1 %

std::string radiusLabel(double radius) {
  char text[32];
  std::snprintf(text, sizeof text, "R=%g mm", radius * 1e3);
  return text;
}

ValidationRow relativeRow(std::string check, std::string reference, double measured,
                          double expected, double tolerance, std::string unit) {
  ValidationRow row{std::move(check), std::move(reference), measured, expected, tolerance, false,
                    std::move(unit), false};
  row.pass = std::isfinite(measured) && std::fabs(measured - expected) <= tolerance * std::fabs(expected);
  return row;
}

ValidationRow absoluteRow(std::string check, std::string reference, double measured,
                          double expected, double tolerance, std::string unit) {
  ValidationRow row{std::move(check), std::move(reference), measured, expected, tolerance, true,
                    std::move(unit), false};
  row.pass = std::isfinite(measured) && std::fabs(measured - expected) <= tolerance;
  return row;
}

bool isAdiabaticDefault(const OscillatorModel& m) {
  return m.polytropic == PolytropicModel::Adiabatic && m.surfaceTension && !m.vapour && !m.hydrostatic;
}
bool isThermalDefault(const OscillatorModel& m) {
  return m.polytropic == PolytropicModel::Thermal && m.surfaceTension && !m.vapour && !m.hydrostatic;
}

/// Damped frequency f_d = √(ω₀² − β²)/2π [Hz] of a deep bubble under the settings.
double dampedFrequency(const OscillatorConstants& c) {
  return std::sqrt(c.angularFrequency * c.angularFrequency - c.decayRate * c.decayRate) /
         (2.0 * std::numbers::pi);
}

/// The bubble set for a single bubble born at t, with an optional constant depth.
BubbleTrack singleBubble(double radius, double birth, std::optional<double> depth, double transfer) {
  BubbleTrack b;
  b.radius = radius;
  b.birth = birth;
  if (depth || transfer != 1.0) {
    b.track.push_back({birth, depth.value_or(1e3), {transfer}, std::nullopt});
  }
  return b;
}

void deepBubbleRows(const ReferenceBubble& ref, const SynthesisSettings& s,
                    std::vector<ValidationRow>& rows) {
  const OscillatorConstants c =
      bubbleOscillator(ref.radius, s.liquid.ambientPressure, s.liquid, s.model);
  const std::vector<float> x = renderSingleBubble(ref.radius, std::nullopt, 1.0, s);
  const std::string r = radiusLabel(ref.radius);
  const double f = fftPeakFrequency(x, s.sampleRate);
  rows.push_back(relativeRow("frequency " + r, "model f_d", f, dampedFrequency(c), kFrequencyTolerance, "Hz"));
  if (isAdiabaticDefault(s.model))
    rows.push_back(relativeRow("frequency " + r, "T1 sigma, kappa=gamma", f, ref.fAdiabatic, kFrequencyTolerance, "Hz"));
  if (isThermalDefault(s.model))
    rows.push_back(relativeRow("frequency " + r, "T1 sigma, kappa_eff", f, ref.fThermal, kFrequencyTolerance, "Hz"));

  const DampedToneEstimate pencil = matrixPencilEstimate(x, s.sampleRate);
  const double hilbert = hilbertDecayRate(x, s.sampleRate, f);
  rows.push_back(relativeRow("decay (matrix pencil) " + r, "model beta", pencil.decayRate, c.decayRate, kDecayTolerance, "1/s"));
  rows.push_back(relativeRow("decay (Hilbert) " + r, "model beta", hilbert, c.decayRate, kDecayTolerance, "1/s"));
  if (s.model.damping == DampingModel::VanDenDoel)
    rows.push_back(relativeRow("decay (matrix pencil) " + r, "T2b van den Doel d", pencil.decayRate, ref.vanDenDoel, kDecayTolerance, "1/s"));
  else if (isAdiabaticDefault(s.model))
    rows.push_back(relativeRow("decay (matrix pencil) " + r, "T2a Devin beta", pencil.decayRate, ref.betaDevin, kDecayTolerance, "1/s"));
  else if (isThermalDefault(s.model))
    rows.push_back(relativeRow("decay (matrix pencil) " + r, "T2b beta Phi", pencil.decayRate, ref.betaThermal, kDecayTolerance, "1/s"));

  const double amplitude = fitDampedSineAmplitude(x, s.sampleRate, dampedFrequency(c), c.decayRate);
  rows.push_back(relativeRow("amplitude at 1 m " + r, "model excitation", amplitude, c.amplitude, kAmplitudeTolerance, "Pa"));
  if (isAdiabaticDefault(s.model) && s.model.excitation == ExcitationModel::NeckCollapseJet)
    rows.push_back(relativeRow("amplitude at 1 m " + r, "T7 jet p(1 m)", amplitude, ref.jetPressure, kAmplitudeTolerance, "Pa"));
}

void depthShiftRows(const SynthesisSettings& s, std::vector<ValidationRow>& rows) {
  for (const double radius : {1e-3, 2e-3}) {
    const double deep = fftPeakFrequency(renderSingleBubble(radius, std::nullopt, 1.0, s), s.sampleRate);
    for (const double depthOverRadius : {1.5, 2.0, 5.0}) {
      const double depth = depthOverRadius * radius;
      const double shifted = fftPeakFrequency(renderSingleBubble(radius, depth, 1.0, s), s.sampleRate);
      char check[96];
      std::snprintf(check, sizeof check, "depth shift %s h=%gR", radiusLabel(radius).c_str(), depthOverRadius);
      rows.push_back(relativeRow(check, "Strasberg (1-x-x^4)^-1/2", shifted / deep,
                                 freeSurfaceFrequencyRatio(radius, depth), kShiftTolerance, "f/f_inf"));
    }
  }
}

void cutoffRow(const SynthesisSettings& s, std::vector<ValidationRow>& rows) {
  const double radius = 1e-3;
  const OscillatorConstants c = bubbleOscillator(radius, s.liquid.ambientPressure, s.liquid, s.model);
  SynthesisSettings open = s;
  open.duration = 2.0 * decayTime(c.decayRate, s.cutoffDecibels);  // room after the cut-off
  const std::vector<float> x = renderSingleBubble(radius, std::nullopt, 1.0, open);
  std::size_t last = 0;
  for (std::size_t n = 0; n < x.size(); ++n)
    if (x[n] != 0.0f) last = n;
  rows.push_back(absoluteRow("-90 dB cut-off R=1 mm", "(90/20) ln10 / beta", static_cast<double>(last + 1) / s.sampleRate,
                             decayTime(c.decayRate, s.cutoffDecibels), kBlockSamples / s.sampleRate, "s"));
}

double maxAbs(const std::vector<float>& x) {
  double m = 0.0;
  for (float v : x) m = std::max(m, static_cast<double>(std::fabs(v)));
  return m;
}

void linearityRows(const SynthesisSettings& s, std::vector<ValidationRow>& rows) {
  BubbleTrackSet both, a, b;
  a.bubbles = {singleBubble(1e-3, 0.0101, std::nullopt, 1.0)};
  b.bubbles = {singleBubble(2e-3, 0.01237, 6e-3, 0.8)};
  both.bubbles = {a.bubbles[0], b.bubbles[0]};
  SynthesisSettings fixed = s;
  fixed.duration = 0.2;
  const auto xa = synthesize(a, fixed).channels[0], xb = synthesize(b, fixed).channels[0];
  const auto xab = synthesize(both, fixed).channels[0];
  double err = 0.0;
  for (std::size_t n = 0; n < xab.size(); ++n)
    err = std::max(err, std::fabs(static_cast<double>(xab[n]) - (static_cast<double>(xa[n]) + xb[n])));
  rows.push_back(absoluteRow("superposition of two bubbles", "x_ab = x_a + x_b", err / maxAbs(xab), 0.0, kLinearityTolerance, "rel. to peak"));

  constexpr double k = 0.37;  // any factor: the transfer enters linearly
  constexpr double depth = 0.05;  // the same track for both; only the transfer differs
  const auto x1 = renderSingleBubble(1e-3, depth, 1.0, fixed);
  const auto xk = renderSingleBubble(1e-3, depth, k, fixed);
  double errK = 0.0;
  for (std::size_t n = 0; n < x1.size(); ++n) errK = std::max(errK, std::fabs(xk[n] - k * x1[n]));
  rows.push_back(absoluteRow("transfer scaling x0.37", "x_k = k x_1", errK / (k * maxAbs(x1)), 0.0, kLinearityTolerance, "rel. to peak"));
}

/// Radius [m] whose deep damped frequency is exactly Nyquist under the settings (bisection on
/// f_d(R), which falls monotonically with R).
double nyquistRadius(double sampleRate, const SynthesisSettings& s) {
  double small = 1e-6, large = 1e-2;
  for (int i = 0; i < 100; ++i) {
    const double mid = std::sqrt(small * large);
    const double f = dampedFrequency(bubbleOscillator(mid, s.liquid.ambientPressure, s.liquid, s.model));
    (f > sampleRate / 2 ? small : large) = mid;
  }
  return std::sqrt(small * large);
}

void nyquistRows(const SynthesisSettings& s, std::vector<ValidationRow>& rows) {
  // Smallest radius below Nyquist, adiabatic + σ: 0.1375 mm at 48 kHz, 0.1496 mm at 44.1 kHz
  // (physics.md §3, undamped f₀; damping lowers f by < 0.1 % there, so 0.5 % tolerance).
  constexpr double kThresholdTolerance = 0.005;
  for (const auto& [rate, tableRadius] : {std::pair{48000.0, 0.1375e-3}, std::pair{44100.0, 0.1496e-3}}) {
    const double threshold = nyquistRadius(rate, s);
    char check[96];
    std::snprintf(check, sizeof check, "Nyquist radius at %g kHz", rate / 1000);
    if (isAdiabaticDefault(s.model))
      rows.push_back(relativeRow(check, "physics.md section 3", threshold, tableRadius, kThresholdTolerance, "m"));
    // One bubble 2 % below the threshold radius must be dropped, one 2 % above kept.
    BubbleTrackSet set;
    set.bubbles = {singleBubble(0.98 * threshold, 0.0, std::nullopt, 1.0),
                   singleBubble(1.02 * threshold, 0.0, std::nullopt, 1.0)};
    SynthesisSettings at = s;
    at.sampleRate = rate;
    const SynthesisReport r = synthesize(set, at).report;
    std::snprintf(check, sizeof check, "Nyquist guard %g kHz: dropped of 0.98, 1.02 R_N", rate / 1000);
    rows.push_back(absoluteRow(check, "1 (only the smaller)", static_cast<double>(r.bubblesAboveNyquist), 1.0, 0.0, "bubbles"));
  }
}

void chirpRow(const SynthesisSettings& s, std::vector<ValidationRow>& rows) {
  SynthesisSettings chirp = s;
  chirp.model.chirp = true;
  const double radius = 1e-3;
  const OscillatorConstants c = bubbleOscillator(radius, s.liquid.ambientPressure, s.liquid, chirp.model);
  const std::vector<float> x = renderSingleBubble(radius, std::nullopt, 1.0, chirp);
  const double t60 = decayTime(c.decayRate, 60.0);
  const std::vector<FrequencyAtTime> f = zeroCrossingFrequencies(x, s.sampleRate);
  const auto at = std::min_element(f.begin(), f.end(), [&](const FrequencyAtTime& a, const FrequencyAtTime& b) {
    return std::fabs(a.time - t60) < std::fabs(b.time - t60);
  });
  const double measured = at == f.end() ? NAN : at->frequency / dampedFrequency(c);
  rows.push_back(relativeRow("chirp rise at -60 dB R=1 mm", "1 + xi ln 1000", measured,
                             1.0 + chirp.model.chirpRiseFactor * std::log(1000.0), kChirpTolerance, "f/f0"));
}

}  // namespace

std::vector<float> renderSingleBubble(double radius, std::optional<double> depth, double transfer,
                                      const SynthesisSettings& settings) {
  BubbleTrackSet set;
  set.sampleRate = settings.sampleRate;
  set.bubbles = {singleBubble(radius, 0.0, depth, transfer)};
  return synthesize(set, settings).channels.at(0);
}

double fitDampedSineAmplitude(const std::vector<float>& x, double sampleRate, double frequency,
                              double decayRate) {
  double xy = 0.0, yy = 0.0;
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = static_cast<double>(n) / sampleRate;
    const double y = std::exp(-decayRate * t) * std::sin(2.0 * std::numbers::pi * frequency * t);
    xy += x[n] * y;
    yy += y * y;
  }
  return xy / yy;
}

std::vector<ValidationRow> validateBubbleAcoustics(const SynthesisSettings& settings,
                                                   const ProgressCallback& progress) {
  std::vector<ValidationRow> rows;
  const double steps = kReference.size() + 5.0;
  double done = 0.0;
  const auto step = [&] {
    if (progress) progress(++done / steps);
  };
  for (const ReferenceBubble& ref : kReference) {
    deepBubbleRows(ref, settings, rows);
    step();
  }
  depthShiftRows(settings, rows);
  step();
  cutoffRow(settings, rows);
  step();
  linearityRows(settings, rows);
  step();
  nyquistRows(settings, rows);
  step();
  chirpRow(settings, rows);
  step();
  return rows;
}

}  // namespace fluidsound::acoustics
