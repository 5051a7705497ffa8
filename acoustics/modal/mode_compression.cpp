// acoustics/modal/mode_compression.cpp — see mode_compression.h.
#include "acoustics/modal/mode_compression.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fluidsound::acoustics {
namespace {

constexpr double kLowFrequencyLimit = 3.6;    // [Hz] below 500 Hz (Zwicker & Fastl §7.2)
constexpr double kRelativeLimit = 0.007;      // [-] of f above 500 Hz

}  // namespace

double frequencyDiscriminationLimit(double frequency) {
  return std::max(kLowFrequencyLimit, kRelativeLimit * frequency);
}

ModeGroups groupIndistinguishableModes(std::span<const double> frequencies) {
  ModeGroups groups;
  groups.group.reserve(frequencies.size());
  double previous = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < frequencies.size(); ++i) {
    const double f = frequencies[i];
    if (!std::isfinite(f) || f < previous)
      throw std::invalid_argument("groupIndistinguishableModes: frequencies must be finite and ascending");
    previous = f;
    const bool joins = !groups.first.empty() &&
                       f - frequencies[groups.first.back()] < frequencyDiscriminationLimit(frequencies[groups.first.back()]);
    if (!joins) groups.first.push_back(i);
    groups.group.push_back(groups.first.size() - 1);
  }
  return groups;
}

double truncationTime(double amplitude, double decayRate, double eventPeak, double threshold) {
  const double floor = threshold * eventPeak;
  if (!(amplitude > floor) || !(decayRate > 0.0)) return amplitude > floor ? std::numeric_limits<double>::infinity() : 0.0;
  return std::log(amplitude / floor) / decayRate;
}

}  // namespace fluidsound::acoustics
