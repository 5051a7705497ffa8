// sim/bubbles/bubble_history.h — bubble model output: each bubble's radius, birth and per-frame samples
// (time, centre, depth below the free surface), the sim-level record that io/ turns into
// `fluidsound.bubbles/1` tracks (DESIGN.md, "The bubble-track contract"; docs/bubbles.md).
#pragma once

#include <optional>
#include <ostream>
#include <vector>

#include "sim/fluid/grid.h"

namespace fluidsound::sim {

/// One sample of a bubble's track (value type).
struct BubbleSample {
  double time = 0.0;             ///< [s]
  Vec3 position{0.0, 0.0, 0.0};  ///< bubble centre [m], world space
  /// Distance from the centre to the free surface [m]: −φ interpolated at the centre; always
  /// > the bubble's radius (a bubble whose depth reaches its radius has ended).
  double depth = 0.0;
  bool operator==(const BubbleSample&) const = default;
};

/// The life of one bubble (value type).
struct BubbleHistory {
  double radius = 0.0;  ///< equilibrium radius [m], > 0, constant
  /// Birth time [s]: continuous, anywhere inside the step that made the bubble (never quantised
  /// to steps or frames).
  double birth = 0.0;
  /// In strictly increasing time: the first at `birth` (where and how deep it was made), then one
  /// per frame (BubbleModel::sampleFrame) while the bubble lives.
  std::vector<BubbleSample> samples;
  /// When the model ended the bubble [s]: the interpolated time its depth reached its radius, or
  /// the end of the step in which it left the domain or entered a solid. Empty while it lives.
  std::optional<double> death;
  bool operator==(const BubbleHistory&) const = default;
};

inline std::ostream& operator<<(std::ostream& out, const BubbleSample& s) {
  return out << "{t " << s.time << " s, x (" << s.position[0] << ", " << s.position[1] << ", " << s.position[2]
             << ") m, depth " << s.depth << " m}";
}

inline std::ostream& operator<<(std::ostream& out, const BubbleHistory& b) {
  out << "{radius " << b.radius << " m, birth " << b.birth << " s, " << b.samples.size() << " samples";
  if (!b.samples.empty()) out << " from " << b.samples.front() << " to " << b.samples.back();
  if (b.death) out << ", death " << *b.death << " s";
  return out << "}";
}

}  // namespace fluidsound::sim
