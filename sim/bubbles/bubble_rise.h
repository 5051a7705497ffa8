// sim/bubbles/bubble_rise.h — bubble model: a bubble as a buoyant point particle carried by the liquid
// (buoyancy, added mass, the liquid's pressure gradient, drag), its terminal rise speed, and a
// time step that is implicit in the drag so any fluid substep keeps it stable.
//
// Equation of motion (point bubble in a non-uniform flow; Maxey & Riley 1983, Phys. Fluids
// 26:883, with the inviscid added-mass force of Auton, Hunt & Prud'homme 1988, JFM 197:241
// [memory]; history and lift forces neglected):
//   ρ_a V dv/dt = ρ_a V g + ρ_w V (Du/Dt − g) + C_A ρ_w V (Du/Dt − dv/dt) + F_D
// where ρ_w V (Du/Dt − g) = −V∇p is the force of the undisturbed liquid's pressure gradient, u and
// Du/Dt the liquid velocity and material acceleration at the bubble, so
//   (ρ_a + C_A ρ_w) V dv/dt = (ρ_a − ρ_w) V g + (1 + C_A) ρ_w V Du/Dt + F_D,
//   F_D = −½ ρ_w C_D π r² |v − u| (v − u).
// In still water the right side is buoyancy plus drag; in liquid falling freely (Du/Dt = g) the
// bubble falls with it. Radii are volume-equivalent radii r (V = 4πr³/3, d = 2r).
#pragma once

#include "sim/fluid/grid.h"

namespace fluidsound::sim {

/// The drag laws of Tomiyama, Kataoka, Zun & Sakaguchi (1998, JSME Int. J. B 41(2):472), one per
/// level of surface contamination. With Re = ρ_w |v − u| d / μ and Eo = |ρ_w − ρ_a| g d² / σ:
///   Contaminated:         C_D = max(24/Re (1 + 0.15 Re^0.687), 8Eo / (3(Eo + 4)))
///   SlightlyContaminated: C_D = max(min(24/Re (1 + 0.15 Re^0.687), 72/Re), 8Eo / (3(Eo + 4)))
///   Pure:                 C_D = max(min(16/Re (1 + 0.15 Re^0.687), 48/Re), 8Eo / (3(Eo + 4)))
/// 24/Re (1 + 0.15 Re^0.687) is the rigid-sphere curve of Schiller & Naumann (1933); 48/Re is
/// Levich's (1962) clean spherical bubble; at terminal speed the Eo term gives exactly Mendelson's
/// (1967) wave-analogy speed U² = 2σ/(ρ_w d) + (Δρ/ρ_w) g d/2 (derivation in bubble_rise.cpp).
/// The three forms were cross-checked against public implementations of Tomiyama's laws; the
/// papers themselves (Tomiyama, Schiller & Naumann, Levich, Mendelson) are cited [memory].
enum class BubbleSurface {
  /// Tap water: surfactants immobilise the interface. Default; the only law checked against
  /// measurements (tests/sim/bubbles/bubble_rise_test.cpp, radii 0.5–4 mm, within 10 %).
  Contaminated,
  SlightlyContaminated,  ///< Not checked against measurements here.
  /// Hyper-clean water: Levich's speed for r ≈ 0.3–0.55 mm, a peak of 0.36 m/s at r ≈ 0.6 mm, then
  /// Mendelson's. Not validated: against Duineveld's measurements in pure water (1995, JFM
  /// 292:325, Fig. 1, as digitised in github.com/CRC-1194/lent, cases/flow-solution/rising-bubble/
  /// three-dimensional/notebooks/BubbleRiseVelocity-Duineveld.csv: r = 0.33, 0.5, 0.6, 0.905,
  /// 0.97 mm → 0.137, 0.261, 0.308, 0.363, 0.354 m/s) it gives 0.118, 0.271, 0.357, 0.300,
  /// 0.291 m/s: within 10 % only near r = 0.4–0.5 and 0.7–0.75 mm, 16 % fast at 0.6 mm and
  /// 17–18 % slow at 0.9–1 mm, where the measured peak lies.
  Pure,
};

/// Liquid and gas properties and the drag law; defaults are water and air at 20 °C, 1 atm.
struct BubbleRiseSettings {
  double liquidDensity = 998.0;       ///< ρ_w [kg/m³] (physics.md §2)
  double gasDensity = 1.204;          ///< ρ_a [kg/m³], air (physics.md §2)
  double liquidViscosity = 1.002e-3;  ///< μ [Pa·s] (physics.md §2)
  double surfaceTension = 0.0728;     ///< σ [N/m], air–water (physics.md §2)
  /// C_A, added-mass coefficient of a sphere in potential flow (Lamb 1932, Hydrodynamics §92
  /// [memory]).
  double addedMassCoefficient = 0.5;
  BubbleSurface surface = BubbleSurface::Contaminated;
  bool operator==(const BubbleRiseSettings&) const = default;
};

/// The liquid at the bubble's position, sampled by the caller from the fluid solver.
struct LiquidAtBubble {
  Vec3 velocity{0.0, 0.0, 0.0};  ///< u [m/s], at the end of the step
  /// Du/Dt [m/s²], the liquid's material acceleration (e.g. the change of the grid velocity at
  /// the bubble over the substep); it carries the pressure-gradient and added-mass forces.
  Vec3 acceleration{0.0, 0.0, 0.0};
};

/// A bubble's kinematic state (value type).
struct BubbleMotion {
  Vec3 position{0.0, 0.0, 0.0};  ///< [m], world space
  Vec3 velocity{0.0, 0.0, 0.0};  ///< [m/s]
  bool operator==(const BubbleMotion&) const = default;
};

/// @brief Drag coefficient C_D of one of Tomiyama et al.'s (1998) laws (see BubbleSurface).
/// @param reynolds  Re = ρ_w |v − u| d / μ, > 0
/// @param eotvos    Eo = |ρ_w − ρ_a| g d² / σ, ≥ 0
/// @throws std::invalid_argument for Re ≤ 0 or Eo < 0 (or NaN)
double bubbleDragCoefficient(double reynolds, double eotvos, BubbleSurface surface);

/// @brief Terminal rise speed [m/s] of a bubble in still liquid: the speed where drag balances
///        buoyancy, ½ ρ_w C_D π r² U² = |ρ_w − ρ_a| (4/3) π r³ g. Independent of C_A.
/// @param radius   volume-equivalent radius r [m], > 0
/// @param gravity  |g| [m/s²], ≥ 0 (0 gives 0)
/// @throws std::invalid_argument for a radius ≤ 0, gravity < 0 or invalid settings
double terminalRiseSpeed(double radius, double gravity, const BubbleRiseSettings& settings = {});

/// @brief Advances one bubble by dt: backward Euler in the drag, explicit in buoyancy and liquid
///        acceleration, then x += dt·v_new. The drag, monotone in the slip speed, is solved for
///        exactly, so the step is unconditionally stable and approaches the terminal speed
///        without overshoot from rest for any dt; its fixed point is the terminal slip exactly.
/// @param radius   volume-equivalent radius r [m], > 0 (constant over the step)
/// @param gravity  g [m/s²], e.g. the scene's {0, −9.81, 0}
/// @param dt       time step [s], ≥ 0 (e.g. a fluid substep, up to ~10 ms and beyond)
/// @throws std::invalid_argument for a radius ≤ 0, dt < 0, non-finite input or invalid settings
BubbleMotion advanceBubble(const BubbleMotion& motion, double radius, const LiquidAtBubble& liquid,
                           const Vec3& gravity, double dt, const BubbleRiseSettings& settings = {});

}  // namespace fluidsound::sim
