// acoustics/transfer/resonator_ring.cpp — see resonator_ring.h.
#include "acoustics/transfer/resonator_ring.h"

namespace fluidsound::acoustics {

std::complex<double> ringAmplitude(std::complex<double> residue, std::complex<double> pole,
                                   double bubbleAngularFrequency, double bubbleDecayRate) {
  const std::complex<double> shifted = pole + bubbleDecayRate;
  const std::complex<double> spectrum =
      bubbleAngularFrequency / (shifted * shifted + bubbleAngularFrequency * bubbleAngularFrequency);
  return 2.0 * residue * spectrum;
}

}  // namespace fluidsound::acoustics
