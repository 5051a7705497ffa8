// acoustics/synthesis/oscillator_kernel.h — which instruction-set version of the oscillator inner loop runs:
// one kernel per x86-64 micro-architecture level (psABI), each shaped for that level's registers.
#pragma once

#include <string_view>

namespace fluidsound::acoustics {

/// The versions of the oscillator inner loop (oscillator_bank.h), by x86-64 level.
enum class OscillatorKernel {
  baseline,  ///< x86-64 (SSE2): 16 registers of 4 floats; no FMA
  avx2,      ///< x86-64-v3 (AVX2 + FMA): 16 registers of 8 floats
  avx512,    ///< x86-64-v4 (AVX-512): 32 registers of 16 floats
};

/// Every kernel, from the narrowest to the widest.
inline constexpr OscillatorKernel kOscillatorKernels[] = {
    OscillatorKernel::baseline, OscillatorKernel::avx2, OscillatorKernel::avx512};

/// @brief A short name for logs and benchmark labels, e.g. "x86-64-v3 (AVX2+FMA) 8 lanes" (no
///        comma: it is a field of the benchmark's CSV).
std::string_view oscillatorKernelName(OscillatorKernel kernel);

/// @brief Whether this CPU has every instruction `kernel` uses (calling one it lacks would
///        fault on an illegal instruction).
bool cpuRunsOscillatorKernel(OscillatorKernel kernel);

/// @brief The widest kernel this CPU runs: what the synthesizer uses unless told otherwise.
OscillatorKernel fastestOscillatorKernel();

}  // namespace fluidsound::acoustics
