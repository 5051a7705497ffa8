// acoustics/oscillator_bank.cpp — SIMD inner loop of the synthesizer (see oscillator_bank.h).
// GCC vector extensions give 8 float lanes; target_clones builds an AVX2+FMA version chosen at
// run time on CPUs that have it, and a baseline version for the others.
#include "acoustics/oscillator_bank.h"

namespace fluidsound::acoustics {
namespace {

using Lanes = float __attribute__((vector_size(sizeof(float) * kOscillatorLanes)));

inline Lanes load(const float* p) {
  Lanes v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
inline void store(float* p, Lanes v) { __builtin_memcpy(p, &v, sizeof v); }

template <int Listeners, bool Masked>
__attribute__((always_inline)) inline void accumulate(const OscillatorGroup& g, int listeners,
                                                      float* acc) {
  const int channels = Listeners > 0 ? Listeners : listeners;
  Lanes zr = load(g.zRe), zi = load(g.zIm), rr = load(g.rRe), ri = load(g.rIm);
  const Lanes cr = load(g.cRe), ci = load(g.cIm);
  Lanes gain[kMaxListeners], step[kMaxListeners];
  for (int l = 0; l < channels; ++l) {
    gain[l] = load(g.gain[l]);
    step[l] = load(g.gainStep[l]);
  }
  const Lanes first = load(g.firstSample);
  const Lanes zero = {};
  for (int n = 0; n < kBlockSamples; ++n) {
    float* accN = acc + n * kOscillatorLanes;
    // The gain is evaluated, not accumulated, at each sample (g₀ + step·k), so its rounding does
    // not grow along the block and a scaled transfer scales the output to float precision.
    const Lanes since = (zero + static_cast<float>(n)) - first;
    const Lanes nzr = zr * rr - zi * ri, nzi = zr * ri + zi * rr;
    const Lanes nrr = rr * cr - ri * ci, nri = rr * ci + ri * cr;
    if constexpr (Masked) {
      // Before its first sample a lane adds nothing and its state stands still.
      const auto on = since >= zero;
      for (int l = 0; l < channels; ++l) {
        float* a = accN + l * kBlockSamples * kOscillatorLanes;
        store(a, load(a) + (on ? (gain[l] + step[l] * since) * zi : zero));
      }
      zr = on ? nzr : zr;
      zi = on ? nzi : zi;
      rr = on ? nrr : rr;
      ri = on ? nri : ri;
    } else {
      for (int l = 0; l < channels; ++l) {
        float* a = accN + l * kBlockSamples * kOscillatorLanes;
        store(a, load(a) + (gain[l] + step[l] * since) * zi);
      }
      zr = nzr;
      zi = nzi;
      rr = nrr;
      ri = nri;
    }
  }
}

}  // namespace

__attribute__((target_clones("arch=x86-64-v3", "default")))
void accumulateOscillatorGroup(const OscillatorGroup& group, int listeners, bool masked,
                               float* accumulator) {
  // Fixed listener counts let the compiler keep gains in registers for the common cases.
  if (masked) {
    switch (listeners) {
      case 1: return accumulate<1, true>(group, listeners, accumulator);
      case 2: return accumulate<2, true>(group, listeners, accumulator);
      default: return accumulate<0, true>(group, listeners, accumulator);
    }
  }
  switch (listeners) {
    case 1: return accumulate<1, false>(group, listeners, accumulator);
    case 2: return accumulate<2, false>(group, listeners, accumulator);
    default: return accumulate<0, false>(group, listeners, accumulator);
  }
}

}  // namespace fluidsound::acoustics
