// tests/support/printed_tolerance.h — the tolerance for a value of the printed tables of
// docs/physics.md (T1, T2a, T2b, T7), shared by the acoustics tests that check them.
#pragma once

#include <algorithm>
#include <cmath>

namespace fluidsound::test {

/// Tolerance for a printed table value: half a unit of its last printed digit (the rounding of the
/// table), or 2e-5 relative (double-precision evaluations of the same formula agree far better; the
/// floor only covers the table's own rounding when the last digit is coarse), whichever is larger.
inline double printedTolerance(double value, double lastDigit) {
  return std::max(0.5 * lastDigit, 2e-5 * std::abs(value));
}

}  // namespace fluidsound::test
