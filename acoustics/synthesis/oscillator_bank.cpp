// acoustics/synthesis/oscillator_bank.cpp — SIMD inner loop of the synthesizer (see oscillator_bank.h).
// GCC vector extensions; one function per kernel (oscillator_kernel.h), compiled for its x86-64
// level and running a group in slices of that level's register width: one 16-lane slice on
// AVX-512, 8-lane halves on AVX2, 4-lane quarters on the baseline, so that a slice's state stays
// in registers (16-lane vectors on AVX2 spilled and scalarised). The caller picks the kernel.
// Bits differ between the fusing kernels and the baseline (FMA), never between runs or threads.
#include "acoustics/synthesis/oscillator_bank.h"

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
__attribute__((always_inline)) inline V load(const float* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
template <typename V>
__attribute__((always_inline)) inline void store(float* p, V v) {
  __builtin_memcpy(p, &v, sizeof v);
}

/// The transfer of listener l at the first sample and its change per sample, for one slice.
/// Read from the group at every sample rather than held in registers: the loads are cheap, and
/// the registers then hold only the oscillators' state, so no kernel spills in its sample loop.
template <typename Lanes>
__attribute__((always_inline)) inline Lanes gainAt(const OscillatorGroup& g, int l, int lane0,
                                                   Lanes since) {
  return load<Lanes>(g.gain[l] + lane0) + load<Lanes>(g.gainStep[l] + lane0) * since;
}

/// One block of Slices slices of Width lanes from lane0 on, on vectors of Width floats, the slices
/// interleaved sample by sample (two independent recurrences hide each other's latency). Every
/// kernel runs this same per-lane arithmetic, so a lane's bits depend neither on the width nor on
/// the interleaving. Only z, r and the sample count live in registers; c and the gains are read
/// from the group (cheap loads), so that two 8-lane slices fit AVX2's 16 registers.
template <int Width, int Slices, int Listeners, bool Masked>
__attribute__((always_inline)) inline void accumulateSlices(const OscillatorGroup& g, int lane0,
                                                            int listeners, float* acc) {
  using Lanes = Vector<Width>;
  const int channels = Listeners > 0 ? Listeners : listeners;
  const Lanes zero = {}, one = zero + 1.0f;
  Lanes zr[Slices], zi[Slices], rr[Slices], ri[Slices], since[Slices];
#pragma GCC unroll 2
  for (int h = 0; h < Slices; ++h) {
    const int first = lane0 + h * Width;
    zr[h] = load<Lanes>(g.zRe + first);
    zi[h] = load<Lanes>(g.zIm + first);
    rr[h] = load<Lanes>(g.rRe + first);
    ri[h] = load<Lanes>(g.rIm + first);
    // Samples since each lane's first, counted in the vector (exact: integers below 2²⁴), so
    // no scalar conversion and broadcast per sample.
    since[h] = zero - load<Lanes>(g.firstSample + first);
  }
  for (int n = 0; n < kBlockSamples; ++n) {
#pragma GCC unroll 2
    for (int h = 0; h < Slices; ++h) {
      const int first = lane0 + h * Width;
      float* accN = acc + n * kOscillatorLanes + first;
      const Lanes cr = load<Lanes>(g.cRe + first), ci = load<Lanes>(g.cIm + first);
      const Lanes nzr = zr[h] * rr[h] - zi[h] * ri[h], nzi = zr[h] * ri[h] + zi[h] * rr[h];
      const Lanes nrr = rr[h] * cr - ri[h] * ci, nri = rr[h] * ci + ri[h] * cr;
      // The gain is evaluated, not accumulated, at each sample (g₀ + step·k), so its rounding
      // does not grow along the block and a scaled transfer scales the output to float precision.
      if constexpr (Masked) {
        // Before its first sample a lane adds nothing and its state stands still.
        const auto on = since[h] >= zero;
        for (int l = 0; l < channels; ++l) {
          float* a = accN + l * kBlockSamples * kOscillatorLanes;
          store(a, load<Lanes>(a) + (on ? gainAt(g, l, first, since[h]) * zi[h] : zero));
        }
        zr[h] = on ? nzr : zr[h];
        zi[h] = on ? nzi : zi[h];
        rr[h] = on ? nrr : rr[h];
        ri[h] = on ? nri : ri[h];
      } else {
        for (int l = 0; l < channels; ++l) {
          float* a = accN + l * kBlockSamples * kOscillatorLanes;
          store(a, load<Lanes>(a) + gainAt(g, l, first, since[h]) * zi[h]);
        }
        zr[h] = nzr;
        zi[h] = nzi;
        rr[h] = nrr;
        ri[h] = nri;
      }
      since[h] += one;
    }
  }
}

/// The first `activeLanes` lanes of a group in slices no wider than NativeWidth (the kernel's
/// register) and no narrower than 4: a tail of at most 4 lanes runs on a 4-lane vector. On AVX2
/// a full group with one or two listeners runs its two 8-lane halves interleaved; masked groups
/// (a few per block) and more listeners would not fit the registers that way, and run the halves
/// one after the other.
template <int NativeWidth, int Listeners, bool Masked>
__attribute__((always_inline)) inline void accumulateGroupSlices(const OscillatorGroup& g,
                                                                 int listeners, float* acc,
                                                                 int activeLanes) {
  int lane0 = 0;
  if constexpr (NativeWidth > 8) {
    if (activeLanes > 8) return accumulateSlices<16, 1, Listeners, Masked>(g, 0, listeners, acc);
  }
  if constexpr (NativeWidth == 8 && !Masked && Listeners > 0) {
    if (activeLanes > 12) return accumulateSlices<8, 2, Listeners, Masked>(g, 0, listeners, acc);
  }
  if constexpr (NativeWidth > 4) {
    for (; activeLanes - lane0 > 4; lane0 += 8)
      accumulateSlices<8, 1, Listeners, Masked>(g, lane0, listeners, acc);
  }
  for (; lane0 < activeLanes; lane0 += 4)
    accumulateSlices<4, 1, Listeners, Masked>(g, lane0, listeners, acc);
}

template <int NativeWidth>
__attribute__((always_inline)) inline void accumulateGroup(const OscillatorGroup& group,
                                                           int listeners, bool masked,
                                                           float* accumulator, int activeLanes) {
  static_assert(kOscillatorLanes == 16, "slices assume 16 lanes");
  // Fixed listener counts for the common cases, so the listener loop is unrolled.
  if (masked) {
    switch (listeners) {
      case 1:
        return accumulateGroupSlices<NativeWidth, 1, true>(group, listeners, accumulator,
                                                           activeLanes);
      case 2:
        return accumulateGroupSlices<NativeWidth, 2, true>(group, listeners, accumulator,
                                                           activeLanes);
      default:
        return accumulateGroupSlices<NativeWidth, 0, true>(group, listeners, accumulator,
                                                           activeLanes);
    }
  }
  switch (listeners) {
    case 1:
      return accumulateGroupSlices<NativeWidth, 1, false>(group, listeners, accumulator,
                                                          activeLanes);
    case 2:
      return accumulateGroupSlices<NativeWidth, 2, false>(group, listeners, accumulator,
                                                          activeLanes);
    default:
      return accumulateGroupSlices<NativeWidth, 0, false>(group, listeners, accumulator,
                                                          activeLanes);
  }
}

// One function per kernel, each compiled for its x86-64 level (the names
// cpuRunsOscillatorKernel checks) and running the slices that fit that level's registers; not
// inlined, so each has its own symbol for a look at its code (tools/check_kernel_code.py).
__attribute__((target("arch=x86-64-v4"), noinline)) void accumulateAvx512(
    const OscillatorGroup& group, int listeners, bool masked, float* accumulator, int activeLanes) {
  accumulateGroup<16>(group, listeners, masked, accumulator, activeLanes);
}

__attribute__((target("arch=x86-64-v3"), noinline)) void accumulateAvx2(
    const OscillatorGroup& group, int listeners, bool masked, float* accumulator, int activeLanes) {
  accumulateGroup<8>(group, listeners, masked, accumulator, activeLanes);
}

// arch=x86-64 also when the file is built with -march=native: the baseline never fuses.
__attribute__((target("arch=x86-64"), noinline)) void accumulateBaseline(
    const OscillatorGroup& group, int listeners, bool masked, float* accumulator, int activeLanes) {
  accumulateGroup<4>(group, listeners, masked, accumulator, activeLanes);
}

}  // namespace

void accumulateOscillatorGroup(OscillatorKernel kernel, const OscillatorGroup& group, int listeners,
                               bool masked, float* accumulator, int activeLanes) {
  switch (kernel) {
    case OscillatorKernel::avx512:
      return accumulateAvx512(group, listeners, masked, accumulator, activeLanes);
    case OscillatorKernel::avx2:
      return accumulateAvx2(group, listeners, masked, accumulator, activeLanes);
    case OscillatorKernel::baseline:
      return accumulateBaseline(group, listeners, masked, accumulator, activeLanes);
  }
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
__attribute__((always_inline)) inline void sumLanes(const float* accumulator, int listeners,
                                                    int count, float* const* output) {
  for (int l = 0; l < listeners; ++l) {
    const float* a = accumulator + l * kBlockSamples * kOscillatorLanes;
    for (int n = 0; n < count; ++n) output[l][n] = pairwiseSum<Width>(a + n * kOscillatorLanes);
  }
}

}  // namespace

// The lane sums are additions only, the same bits in every clone, and run once per block (not
// once per group): the resolver's choice is enough here.
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void
sumOscillatorLanes(const float* accumulator, int listeners, int count, float* const* output,
                   int activeLanes) {
  static_assert(kOscillatorLanes == 16, "widths below assume 16 lanes");
  if (activeLanes <= 4) return sumLanes<4>(accumulator, listeners, count, output);
  if (activeLanes <= 8) return sumLanes<8>(accumulator, listeners, count, output);
  return sumLanes<16>(accumulator, listeners, count, output);
}

}  // namespace fluidsound::acoustics
