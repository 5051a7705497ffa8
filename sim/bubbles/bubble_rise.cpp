// sim/bubbles/bubble_rise.cpp — see bubble_rise.h.
//
// Why Tomiyama's contaminated law as the default. Water in a glass, a sink or a pond is tap or
// natural water: trace surfactants gather on a rising bubble's surface and immobilise it, so a
// bubble of up to ~1 mm radius drags like a rigid sphere, and the clean-water peak (≈ 0.35 m/s
// near r ≈ 0.9 mm) is not seen (Clift, Grace & Weber 1978, ch. 7 [memory]). The contaminated law
// is the larger of two physical limits, with no constant fitted to the test's table:
//  - the rigid-sphere standard drag curve of Schiller & Naumann (1933), 24/Re (1 + 0.15 Re^0.687),
//    which governs small, spherical bubbles;
//  - the deformed-bubble term 8Eo/(3(Eo + 4)), which at terminal speed reproduces Mendelson's
//    (1967) wave analogy exactly. Terminal speed: ½ρ_w C_D πr²U² = Δρ (4/3)πr³ g, so
//      C_D U² = (4/3) g d Δρ/ρ_w,   Eo = Δρ g d²/σ,
//      U² = (4/3) g d (Δρ/ρ_w) · 3(Eo + 4)/(8Eo) = (Δρ/ρ_w) g d/2 + 2σ/(ρ_w d),
//    the speed of millimetre bubbles whose shape is set by surface tension and gravity.
// The measurements it is checked against (tap water, r = 0.5–4 mm) are in the test.
#include "sim/bubbles/bubble_rise.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fluidsound::sim {

namespace {

[[noreturn]] void reject(const std::string& what, double value) {
  std::ostringstream message;
  message << what << ", got " << value;
  throw std::invalid_argument(message.str());
}

void requirePositive(const char* name, double value, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0))
    reject(std::string(name) + " must be a finite number > 0 " + unit, value);
}

void requireNonNegative(const char* name, double value, const char* unit) {
  if (!(std::isfinite(value) && value >= 0.0))
    reject(std::string(name) + " must be a finite number ≥ 0 " + unit, value);
}

void requireFinite(const char* name, const Vec3& v) {
  for (double c : v)
    if (!std::isfinite(c)) reject(std::string(name) + " must be finite", c);
}

void validate(const BubbleRiseSettings& s) {
  requirePositive("BubbleRiseSettings.liquidDensity", s.liquidDensity, "(kg/m³)");
  requireNonNegative("BubbleRiseSettings.gasDensity", s.gasDensity, "(kg/m³)");
  requirePositive("BubbleRiseSettings.liquidViscosity", s.liquidViscosity, "(Pa·s)");
  requirePositive("BubbleRiseSettings.surfaceTension", s.surfaceTension, "(N/m)");
  requireNonNegative("BubbleRiseSettings.addedMassCoefficient", s.addedMassCoefficient, "");
  // The bubble's inertia (ρ_a + C_A ρ_w)V must not vanish: a massless bubble has no dv/dt.
  requirePositive("BubbleRiseSettings: gasDensity + addedMassCoefficient·liquidDensity",
                  s.gasDensity + s.addedMassCoefficient * s.liquidDensity, "(kg/m³)");
}

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/// C_D·Re of Tomiyama et al.'s (1998) laws (bubble_rise.h): the same law multiplied through by Re,
/// finite as Re → 0 (where it tends to the Stokes value 24, or 16 for the pure law).
double dragTimesReynolds(double reynolds, double eotvos, BubbleSurface surface) {
  const double standardCurve = 24.0 * (1.0 + 0.15 * std::pow(reynolds, 0.687));  // Schiller–Naumann
  const double deformed = reynolds * 8.0 * eotvos / (3.0 * (eotvos + 4.0));
  switch (surface) {
    case BubbleSurface::SlightlyContaminated:
      return std::max(std::min(standardCurve, 72.0), deformed);
    case BubbleSurface::Pure:
      return std::max(std::min(standardCurve * (16.0 / 24.0), 48.0), deformed);
    case BubbleSurface::Contaminated:
      break;
  }
  return std::max(standardCurve, deformed);
}

/// The drag force on one bubble as a function of its slip speed s = |v − u|.
struct Drag {
  Drag(double radius, double gravity, const BubbleRiseSettings& settings)
      : radius_(radius), settings_(settings) {
    const double d = 2.0 * radius;
    eotvos_ = std::abs(settings.liquidDensity - settings.gasDensity) * gravity * d * d /
              settings.surfaceTension;
  }
  /// |F_D| [N] = ½ ρ_w C_D π r² s² = ½ π r² μ s (C_D Re)/d, written with C_D·Re so that it is
  /// finite and linear (Stokes) as s → 0. Strictly increasing in s: C_D·Re never decreases with
  /// Re in any of the three laws (each branch is non-decreasing, and so are min and max of them).
  double force(double slip) const {
    const double d = 2.0 * radius_, mu = settings_.liquidViscosity;
    const double reynolds = settings_.liquidDensity * slip * d / mu;
    return 0.5 * std::numbers::pi * radius_ * radius_ * mu * slip *
           dragTimesReynolds(reynolds, eotvos_, settings_.surface) / d;
  }
  double radius_;
  const BubbleRiseSettings& settings_;
  double eotvos_ = 0.0;
};

/// Relative bracket width at which the root solves stop: near double precision, far below any
/// physical uncertainty, and cheap (Illinois converges superlinearly).
constexpr double kRootTolerance = 1e-14;
/// Cap on Illinois iterations; solves take ~8 on average and ≤ 25 for r = 10 µm–5 cm, dt ≤ 0.1 s.
constexpr int kRootIterations = 200;

/// The root of a continuous increasing f on [lo, hi] with f(lo) ≤ 0 ≤ f(hi), by the Illinois
/// variant of regula falsi (Dowell & Jarratt 1971, BIT 11:168 [memory]): never leaves the bracket.
template <class Function>
double increasingRoot(const Function& f, double lo, double hi) {
  double fLo = f(lo), fHi = f(hi);
  if (fLo >= 0.0) return lo;
  if (fHi <= 0.0) return hi;
  int lastSide = 0;
  for (int iteration = 0; iteration < kRootIterations && hi - lo > kRootTolerance * hi;
       ++iteration) {
    double x = (lo * fHi - hi * fLo) / (fHi - fLo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double fx = f(x);
    if (fx == 0.0) return x;
    if (fx < 0.0) {
      lo = x;
      fLo = fx;
      if (lastSide < 0) fHi *= 0.5;  // the same end moved twice: halve the other's weight
      lastSide = -1;
    } else {
      hi = x;
      fHi = fx;
      if (lastSide > 0) fLo *= 0.5;
      lastSide = 1;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double bubbleDragCoefficient(double reynolds, double eotvos, BubbleSurface surface) {
  requirePositive("bubbleDragCoefficient: reynolds", reynolds, "");
  requireNonNegative("bubbleDragCoefficient: eotvos", eotvos, "");
  return dragTimesReynolds(reynolds, eotvos, surface) / reynolds;
}

double terminalRiseSpeed(double radius, double gravity, const BubbleRiseSettings& settings) {
  validate(settings);
  requirePositive("terminalRiseSpeed: radius", radius, "(metres)");
  requireNonNegative("terminalRiseSpeed: gravity", gravity, "(m/s²)");
  // Drag balances buoyancy: |F_D(U)| = |ρ_w − ρ_a| (4/3)π r³ g.
  const double buoyancy = std::abs(settings.liquidDensity - settings.gasDensity) * 4.0 / 3.0 *
                          std::numbers::pi * radius * radius * radius * gravity;
  if (buoyancy == 0.0) return 0.0;
  const Drag drag(radius, gravity, settings);
  const auto excess = [&](double speed) { return drag.force(speed) - buoyancy; };
  double hi = 1.0;  // m/s; doubled until drag exceeds buoyancy (drag grows without bound)
  for (int doubling = 0; doubling < 64 && excess(hi) < 0.0; ++doubling) hi *= 2.0;
  return increasingRoot(excess, 0.0, hi);
}

BubbleMotion advanceBubble(const BubbleMotion& motion, double radius, const LiquidAtBubble& liquid,
                           const Vec3& gravity, double dt, const BubbleRiseSettings& settings) {
  validate(settings);
  requirePositive("advanceBubble: radius", radius, "(metres)");
  requireNonNegative("advanceBubble: dt", dt, "(seconds)");
  requireFinite("advanceBubble: position", motion.position);
  requireFinite("advanceBubble: velocity", motion.velocity);
  requireFinite("advanceBubble: liquid velocity", liquid.velocity);
  requireFinite("advanceBubble: liquid acceleration", liquid.acceleration);
  requireFinite("advanceBubble: gravity", gravity);

  const double rhoW = settings.liquidDensity, rhoA = settings.gasDensity;
  const double cA = settings.addedMassCoefficient;
  const double inertia = rhoA + cA * rhoW;  // (ρ_a + C_A ρ_w), per unit volume
  const double volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  // Explicit part of dv/dt [m/s²]: ((ρ_a − ρ_w) g + (1 + C_A) ρ_w Du/Dt) / (ρ_a + C_A ρ_w)
  // (bubble_rise.h). Backward Euler in the drag for the slip w = v − u at the step's end:
  //   w' + dt·F_D(|w'|)/((ρ_a + C_A ρ_w)V) · w'/|w'| = (v − u) + dt·forcing ≡ b,
  // so w' is parallel to b and its length s solves s + dt·F_D(s)/m = |b|, whose left side is
  // strictly increasing: one root in [0, |b|].
  Vec3 b;
  for (int a = 0; a < 3; ++a) {
    const double forcing =
        ((rhoA - rhoW) * gravity[a] + (1.0 + cA) * rhoW * liquid.acceleration[a]) / inertia;
    b[a] = motion.velocity[a] - liquid.velocity[a] + dt * forcing;
  }
  const double bLength = norm(b);
  double slip = bLength;
  if (bLength > 0.0 && dt > 0.0) {
    const Drag drag(radius, norm(gravity), settings);
    const double perMass = dt / (inertia * volume);
    slip = increasingRoot([&](double s) { return s + perMass * drag.force(s) - bLength; }, 0.0,
                          bLength);
  }
  BubbleMotion next;
  for (int a = 0; a < 3; ++a) {
    next.velocity[a] = liquid.velocity[a] + (bLength > 0.0 ? b[a] * (slip / bLength) : 0.0);
    next.position[a] = motion.position[a] + dt * next.velocity[a];
  }
  return next;
}

}  // namespace fluidsound::sim
