// acoustics/playback/collision_loudness.cpp — see collision_loudness.h.
#include "acoustics/playback/collision_loudness.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fluidsound::acoustics {
namespace {

/// 20·log10 of an amplitude ratio, clamped to at most 0 dB; −∞ for a zero amplitude.
double attenuationDb(double amplitude, double reference) {
  if (!(reference > 0.0)) throw std::invalid_argument("collision loudness: the recording's reference must be > 0");
  if (!(amplitude >= 0.0)) throw std::invalid_argument("collision loudness: speeds, masses and forces must be >= 0");
  return std::min(0.0, 20.0 * std::log10(amplitude / reference));
}

}  // namespace

double impactGainDb(double normalSpeed, double reducedMass, double referenceSpeed, double referenceMass) {
  return attenuationDb(normalSpeed * std::sqrt(reducedMass), referenceSpeed * std::sqrt(referenceMass));
}

double rubbingGainDb(double normalForce, double speed, double referenceNormalForce, double referenceSpeed) {
  return attenuationDb(std::sqrt(normalForce * speed), std::sqrt(referenceNormalForce * referenceSpeed));
}

double reducedMass(double mass1, double mass2) {
  if (mass1 < 0.0 || mass2 < 0.0) throw std::invalid_argument("reducedMass: masses must be >= 0 (0: static)");
  if (mass1 == 0.0) return mass2;
  if (mass2 == 0.0) return mass1;
  return mass1 * mass2 / (mass1 + mass2);
}

}  // namespace fluidsound::acoustics
