// sim/bubbles/bubble_settings.cpp — see bubble_settings.h.
#include "sim/bubbles/bubble_settings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fluidsound::sim {

namespace {

constexpr const char* kWhere = "BubbleSettings";

/// Throws std::invalid_argument "BubbleSettings.<field> must be <expectation>, got <value>".
[[noreturn]] void rejectField(const char* field, const std::string& expectation, double value) {
  std::ostringstream message;
  message << kWhere << "." << field << " must be " << expectation << ", got " << value;
  throw std::invalid_argument(message.str());
}

void requirePositive(const char* field, double value, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0)) rejectField(field, std::string("a finite number > 0 ") + unit, value);
}

void requireNonNegative(const char* field, double value, const char* unit) {
  if (!(std::isfinite(value) && value >= 0.0)) rejectField(field, std::string("a finite number ≥ 0 ") + unit, value);
}

/// > 0, +∞ allowed (it switches the corresponding mechanism off).
void requirePositiveOrInfinite(const char* field, double value, const char* unit) {
  if (!(value > 0.0)) rejectField(field, std::string("a number > 0 (or +inf) ") + unit, value);
}

/// Runs `check` and prefixes the message of any std::invalid_argument with "BubbleSettings.<part>: ".
template <typename Check>
void withPrefix(const char* part, const Check& check) {
  try {
    check();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(kWhere) + "." + part + ": " + e.what());
  }
}

}  // namespace

double BubbleSettings::minRadius() const {
  return std::visit([](const auto& d) { return d.minRadius; }, sizes);
}

double BubbleSettings::maxRadius() const {
  return std::visit([](const auto& d) { return d.maxRadius; }, sizes);
}

void validateBubbleSettings(const BubbleSettings& s) {
  requirePositive("bandCells", s.bandCells, "(cells)");
  requirePositive("entrainmentDepthCells", s.entrainmentDepthCells, "(cells)");
  requirePositive("entrainmentWindow", s.entrainmentWindow, "(seconds)");
  requirePositiveOrInfinite("entrainmentSpeed", s.entrainmentSpeed, "(m/s)");
  requireNonNegative("probeCells", s.probeCells, "(cells)");
  requirePositive("seedLifetime", s.seedLifetime, "(seconds)");
  requirePositiveOrInfinite("potentialDecayTime", s.potentialDecayTime, "(seconds)");
  requireNonNegative("rate", s.rate, "(creation attempts per second per unit potential)");
  requireNonNegative("jitterCells", s.jitterCells, "(cells)");
  if (s.minSeeds < 1) rejectField("minSeeds", "an integer ≥ 1", s.minSeeds);
  requireNonNegative("neighbourhoodCells", s.neighbourhoodCells, "(cells)");
  requireNonNegative("neighbourhoodRadii", s.neighbourhoodRadii, "(bubble radii)");
  if (s.neighbourhoodCells == 0.0 && s.neighbourhoodRadii == 0.0)
    rejectField("neighbourhoodCells", "> 0 when neighbourhoodRadii is 0 (an empty neighbourhood holds no seed)",
                s.neighbourhoodCells);
  // The sampler checks the bounds and shape (its message names the field, e.g. minRadius).
  withPrefix("sizes", [&] { const BubbleSizeSampler sampler(s.sizes); });
  // The rise model checks its own settings on every call; one call with a valid radius and
  // gravity reaches exactly that check.
  withPrefix("rise", [&] { terminalRiseSpeed(s.minRadius(), 0.0, s.rise); });
}

}  // namespace fluidsound::sim
