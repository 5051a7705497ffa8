// acoustics/synthesis/oscillator_bank_reference.cpp — see oscillator_bank_reference.h. The same operations
// in the same order per lane as the kernels (oscillator_bank.cpp), so only fusion can differ.
#include "acoustics/synthesis/oscillator_bank_reference.h"

namespace fluidsound::acoustics {

void accumulateOscillatorGroupReference(const OscillatorGroup& g, int listeners, bool masked,
                                        float* accumulator, int activeLanes) {
  for (int lane = 0; lane < activeLanes; ++lane) {
    float zr = g.zRe[lane], zi = g.zIm[lane], rr = g.rRe[lane], ri = g.rIm[lane];
    const float cr = g.cRe[lane], ci = g.cIm[lane];
    for (int n = 0; n < kBlockSamples; ++n) {
      const float since = static_cast<float>(n) - g.firstSample[lane];
      // A masked lane adds nothing and stands still before its first sample.
      const bool on = !masked || since >= 0.0f;
      for (int l = 0; l < listeners; ++l) {
        float& a = accumulator[(l * kBlockSamples + n) * kOscillatorLanes + lane];
        const float gain = g.gain[l][lane] + g.gainStep[l][lane] * since;
        a = a + (on ? gain * zi : 0.0f);
      }
      if (!on) continue;
      const float nzr = zr * rr - zi * ri, nzi = zr * ri + zi * rr;
      const float nrr = rr * cr - ri * ci, nri = rr * ci + ri * cr;
      zr = nzr;
      zi = nzi;
      rr = nrr;
      ri = nri;
    }
  }
}

}  // namespace fluidsound::acoustics
