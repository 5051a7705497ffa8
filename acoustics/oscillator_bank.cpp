// acoustics/oscillator_bank.cpp — SIMD inner loop of the synthesizer (see oscillator_bank.h).
// GCC vector extensions give kOscillatorLanes float lanes; target_clones builds AVX-512 and
// AVX2+FMA versions chosen at run time on CPUs that have them, and a baseline for the others.
// Bits may differ between those versions (FMA), never between runs or thread counts on one CPU.
#include "acoustics/oscillator_bank.h"

namespace fluidsound::acoustics {
namespace {

/// Vectors of Width floats: the first Width lanes of a group. A group with few voices runs on a
/// narrower vector; each lane's arithmetic, and so its bits, is the same at any width.
/// (Explicit specialisations: GCC ignores vector_size on an alias template with a dependent size.)
template <int Width>
struct VectorOf;
template <>
struct VectorOf<4> {
  typedef float type __attribute__((vector_size(4 * sizeof(float))));
};
template <>
struct VectorOf<8> {
  typedef float type __attribute__((vector_size(8 * sizeof(float))));
};
template <>
struct VectorOf<16> {
  typedef float type __attribute__((vector_size(16 * sizeof(float))));
};
template <int Width>
using Vector = typename VectorOf<Width>::type;

template <typename V>
inline V load(const float* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
template <typename V>
inline void store(float* p, V v) {
  __builtin_memcpy(p, &v, sizeof v);
}

template <int Width, int Listeners, bool Masked>
__attribute__((always_inline)) inline void accumulate(const OscillatorGroup& g, int listeners,
                                                      float* acc) {
  using Lanes = Vector<Width>;
  const int channels = Listeners > 0 ? Listeners : listeners;
  Lanes zr = load<Lanes>(g.zRe), zi = load<Lanes>(g.zIm), rr = load<Lanes>(g.rRe), ri = load<Lanes>(g.rIm);
  const Lanes cr = load<Lanes>(g.cRe), ci = load<Lanes>(g.cIm);
  Lanes gain[kMaxListeners], step[kMaxListeners];
  for (int l = 0; l < channels; ++l) {
    gain[l] = load<Lanes>(g.gain[l]);
    step[l] = load<Lanes>(g.gainStep[l]);
  }
  const Lanes first = load<Lanes>(g.firstSample);
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
        store(a, load<Lanes>(a) + (on ? (gain[l] + step[l] * since) * zi : zero));
      }
      zr = on ? nzr : zr;
      zi = on ? nzi : zi;
      rr = on ? nrr : rr;
      ri = on ? nri : ri;
    } else {
      for (int l = 0; l < channels; ++l) {
        float* a = accN + l * kBlockSamples * kOscillatorLanes;
        store(a, load<Lanes>(a) + (gain[l] + step[l] * since) * zi);
      }
      zr = nzr;
      zi = nzi;
      rr = nrr;
      ri = nri;
    }
  }
}

template <int Width>
__attribute__((always_inline)) inline void accumulateWidth(const OscillatorGroup& group, int listeners,
                                                           bool masked, float* accumulator) {
  // Fixed listener counts let the compiler keep gains in registers for the common cases.
  if (masked) {
    switch (listeners) {
      case 1: return accumulate<Width, 1, true>(group, listeners, accumulator);
      case 2: return accumulate<Width, 2, true>(group, listeners, accumulator);
      default: return accumulate<Width, 0, true>(group, listeners, accumulator);
    }
  }
  switch (listeners) {
    case 1: return accumulate<Width, 1, false>(group, listeners, accumulator);
    case 2: return accumulate<Width, 2, false>(group, listeners, accumulator);
    default: return accumulate<Width, 0, false>(group, listeners, accumulator);
  }
}

}  // namespace

__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
void accumulateOscillatorGroup(const OscillatorGroup& group, int listeners, bool masked,
                               float* accumulator, int activeLanes) {
  static_assert(kOscillatorLanes == 16, "widths below assume 16 lanes");
  if (activeLanes <= 4) return accumulateWidth<4>(group, listeners, masked, accumulator);
  if (activeLanes <= 8) return accumulateWidth<8>(group, listeners, masked, accumulator);
  return accumulateWidth<16>(group, listeners, masked, accumulator);
}

namespace {

/// The pairwise tree of sumOscillatorLanes over the first Width lanes: s[i] += s[i + Width/2], …
/// Lanes beyond the used ones hold +0, and x + 0 = x, so any Width ≥ the used lanes gives the
/// same bits.
template <int Width>
__attribute__((always_inline)) inline float pairwiseSum(const float* lanes) {
  if constexpr (Width == 1) {
    return lanes[0];
  } else {
    using Half = Vector<(Width / 2 < 4 ? 4 : Width / 2)>;
    if constexpr (Width / 2 < 4) {
      float s[Width / 2];
      for (int i = 0; i < Width / 2; ++i) s[i] = lanes[i] + lanes[i + Width / 2];
      return pairwiseSum<Width / 2>(s);
    } else {
      const Half sum = load<Half>(lanes) + load<Half>(lanes + Width / 2);
      float s[Width / 2];
      __builtin_memcpy(s, &sum, sizeof s);
      return pairwiseSum<Width / 2>(s);
    }
  }
}

template <int Width>
__attribute__((always_inline)) inline void sumLanes(const float* accumulator, int listeners, int count,
                                                    float* const* output) {
  for (int l = 0; l < listeners; ++l) {
    const float* a = accumulator + l * kBlockSamples * kOscillatorLanes;
    for (int n = 0; n < count; ++n) output[l][n] = pairwiseSum<Width>(a + n * kOscillatorLanes);
  }
}

}  // namespace

__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
void sumOscillatorLanes(const float* accumulator, int listeners, int count, float* const* output,
                        int activeLanes) {
  static_assert(kOscillatorLanes == 16, "widths below assume 16 lanes");
  if (activeLanes <= 4) return sumLanes<4>(accumulator, listeners, count, output);
  if (activeLanes <= 8) return sumLanes<8>(accumulator, listeners, count, output);
  return sumLanes<16>(accumulator, listeners, count, output);
}

}  // namespace fluidsound::acoustics
