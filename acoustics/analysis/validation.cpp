// acoustics/analysis/validation.cpp — `fluidsound validate` checks (see validation.h; docs/physics.md §9).
#include "acoustics/analysis/validation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "acoustics/bubble/bubble_oscillator.h"
#include "acoustics/bubble/depth_shift.h"
#include "acoustics/bubble/instantaneous_frequency.h"
#include "acoustics/synthesis/oscillator_bank.h"
#include "acoustics/analysis/tone_analysis.h"

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
                    std::move(unit), false, {}};
  row.pass = std::isfinite(measured) && std::fabs(measured - expected) <= tolerance * std::fabs(expected);
  return row;
}

ValidationRow absoluteRow(std::string check, std::string reference, double measured,
                          double expected, double tolerance, std::string unit) {
  ValidationRow row{std::move(check), std::move(reference), measured, expected, tolerance, true,
                    std::move(unit), false, {}};
  row.pass = std::isfinite(measured) && std::fabs(measured - expected) <= tolerance;
  return row;
}

/// `measure()`, or `fallback` when the estimator cannot measure the signal (silent: the bubble was
/// dropped; too short; not finite): the first such reason goes to `why`, and the rows built on the
/// fallback (NaN) fail and carry it, instead of the validation stopping with an internal error.
template <class T, class Measure>
T measuredOr(T fallback, const Measure& measure, std::string& why) {
  try {
    return measure();
  } catch (const std::invalid_argument& e) {
    if (why.empty()) why = std::string("not measured: ") + e.what();
    return fallback;
  }
}

/// Why a render cannot be measured: silent (the synthesizer dropped the bubble) or not finite.
std::string renderProblem(const std::vector<float>& x) {
  if (std::any_of(x.begin(), x.end(), [](float v) { return !std::isfinite(v); }))
    return "not measured: the render is not finite (the excitation overflows float samples)";
  if (std::all_of(x.begin(), x.end(), [](float v) { return v == 0.0f; }))
    return "not measured: the render is silent (the synthesizer dropped the bubble: its pitch reaches Nyquist)";
  return {};
}

/// Gives `why` to the rows from `first` on whose measurement is not a number.
void explainUnmeasured(std::vector<ValidationRow>& rows, std::size_t first, const std::string& why) {
  for (std::size_t i = first; i < rows.size(); ++i)
    if (!std::isfinite(rows[i].measured) && rows[i].note.empty()) rows[i].note = why.empty() ? "not measured" : why;
}

/// The settings of the checks whose estimators assume a steady pitch (FFT peak, matrix pencil,
/// fixed-frequency amplitude fit, ratio of FFT peaks): the chirp off, every other choice kept. The
/// chirp only multiplies the phase rate by C(t) (docs/synthesis.md), so ω₀, β, A and the depth
/// factor these rows check are the same with it; chirpRow() checks C(t) itself.
SynthesisSettings steadyPitch(const SynthesisSettings& s) {
  SynthesisSettings steady = s;
  steady.model.chirp = false;
  return steady;
}

/// Marks the rows from `first` on as run with the chirp off, when the requested model has it on.
void markSteadyPitch(std::vector<ValidationRow>& rows, std::size_t first, const SynthesisSettings& requested) {
  if (!requested.model.chirp) return;
  for (std::size_t i = first; i < rows.size(); ++i) rows[i].check += " (chirp off)";
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
  const std::size_t first = rows.size();
  const OscillatorConstants c =
      bubbleOscillator(ref.radius, s.liquid.ambientPressure, s.liquid, s.model);
  const std::vector<float> x = renderSingleBubble(ref.radius, std::nullopt, 1.0, s);
  const std::string r = radiusLabel(ref.radius);
  std::string why;
  const double f = measuredOr(NAN, [&] { return fftPeakFrequency(x, s.sampleRate); }, why);
  rows.push_back(relativeRow("frequency " + r, "model f_d", f, dampedFrequency(c), kFrequencyTolerance, "Hz"));
  if (isAdiabaticDefault(s.model))
    rows.push_back(relativeRow("frequency " + r, "T1 sigma, kappa=gamma", f, ref.fAdiabatic, kFrequencyTolerance, "Hz"));
  if (isThermalDefault(s.model))
    rows.push_back(relativeRow("frequency " + r, "T1 sigma, kappa_eff", f, ref.fThermal, kFrequencyTolerance, "Hz"));

  const DampedToneEstimate pencil =
      measuredOr(DampedToneEstimate{NAN, NAN}, [&] { return matrixPencilEstimate(x, s.sampleRate); }, why);
  const double hilbert = measuredOr(NAN, [&] { return hilbertDecayRate(x, s.sampleRate, f); }, why);
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
  explainUnmeasured(rows, first, why);
}

void depthShiftRows(const SynthesisSettings& s, std::vector<ValidationRow>& rows) {
  for (const double radius : {1e-3, 2e-3}) {
    const std::size_t first = rows.size();
    std::string why;
    const auto peak = [&](std::optional<double> depth) {
      const std::vector<float> x = renderSingleBubble(radius, depth, 1.0, s);
      return measuredOr(NAN, [&] { return fftPeakFrequency(x, s.sampleRate); }, why);
    };
    const double deep = peak(std::nullopt);
    for (const double depthOverRadius : {1.5, 2.0, 5.0}) {
      const double depth = depthOverRadius * radius;
      const double shifted = peak(depth);
      char check[96];
      std::snprintf(check, sizeof check, "depth shift %s h=%gR", radiusLabel(radius).c_str(), depthOverRadius);
      rows.push_back(relativeRow(check, "Strasberg (1-x-x^4)^-1/2", shifted / deep,
                                 freeSurfaceFrequencyRatio(radius, depth), kShiftTolerance, "f/f_inf"));
    }
    explainUnmeasured(rows, first, why);
  }
}

void cutoffRow(const SynthesisSettings& s, std::vector<ValidationRow>& rows) {
  const double radius = 1e-3;
  const OscillatorConstants c = bubbleOscillator(radius, s.liquid.ambientPressure, s.liquid, s.model);
  SynthesisSettings open = s;
  open.duration = 2.0 * decayTime(c.decayRate, s.cutoffDecibels);  // room after the cut-off
  const std::vector<float> x = renderSingleBubble(radius, std::nullopt, 1.0, open);
  std::optional<std::size_t> last;
  for (std::size_t n = 0; n < x.size(); ++n)
    if (x[n] != 0.0f) last = n;
  const std::string why = renderProblem(x);
  rows.push_back(absoluteRow("-90 dB cut-off R=1 mm", "(90/20) ln10 / beta",
                             why.empty() ? static_cast<double>(*last + 1) / s.sampleRate : NAN,
                             decayTime(c.decayRate, s.cutoffDecibels), kBlockSamples / s.sampleRate, "s"));
  explainUnmeasured(rows, rows.size() - 1, why);
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
  const std::string whyAb = renderProblem(xab);
  rows.push_back(absoluteRow("superposition of two bubbles", "x_ab = x_a + x_b",
                             whyAb.empty() ? err / maxAbs(xab) : NAN, 0.0, kLinearityTolerance, "rel. to peak"));
  explainUnmeasured(rows, rows.size() - 1, whyAb);

  constexpr double k = 0.37;  // any factor: the transfer enters linearly
  constexpr double depth = 0.05;  // the same track for both; only the transfer differs
  const auto x1 = renderSingleBubble(1e-3, depth, 1.0, fixed);
  const auto xk = renderSingleBubble(1e-3, depth, k, fixed);
  double errK = 0.0;
  for (std::size_t n = 0; n < x1.size(); ++n) errK = std::max(errK, std::fabs(xk[n] - k * x1[n]));
  const std::string whyK = renderProblem(x1);
  rows.push_back(absoluteRow("transfer scaling x0.37", "x_k = k x_1",
                             whyK.empty() ? errK / (k * maxAbs(x1)) : NAN, 0.0, kLinearityTolerance, "rel. to peak"));
  explainUnmeasured(rows, rows.size() - 1, whyK);
}

/// Radius [m] whose deep bubble's highest frequency is exactly Nyquist under the settings: the
/// synthesizer's own criterion (instantaneous_frequency.h: the damped frequency, times the chirp at
/// the cut-off when the chirp is on), by bisection, as it falls monotonically with R.
double nyquistRadius(double sampleRate, const SynthesisSettings& s) {
  const auto peakFrequency = [&s](double radius) {
    BubbleTrack deep;
    deep.radius = radius;
    const RingingBubble ringing = ringingBubble(deep, s.liquid, s.model);
    return peakAngularFrequency(ringing, deep, s.cutoffDecibels, s.liquid, s.model) / (2.0 * std::numbers::pi);
  };
  double small = 1e-6, large = 1e-2;
  for (int i = 0; i < 100; ++i) {
    const double mid = std::sqrt(small * large);
    (peakFrequency(mid) > sampleRate / 2 ? small : large) = mid;
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
    if (isAdiabaticDefault(s.model) && !s.model.chirp)  // the table is for a steady pitch
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
  explainUnmeasured(rows, rows.size() - 1, "not measured: no rising zero crossings in the render");
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
  const SynthesisSettings steady = steadyPitch(settings);
  for (const ReferenceBubble& ref : kReference) {
    const std::size_t first = rows.size();
    deepBubbleRows(ref, steady, rows);
    markSteadyPitch(rows, first, settings);
    step();
  }
  const std::size_t shiftRows = rows.size();
  depthShiftRows(steady, rows);
  markSteadyPitch(rows, shiftRows, settings);
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
