// acoustics/synthesis/oscillator_kernel.cpp — names of the oscillator kernels and which this CPU runs.
#include "acoustics/synthesis/oscillator_kernel.h"

namespace fluidsound::acoustics {

std::string_view oscillatorKernelName(OscillatorKernel kernel) {
  switch (kernel) {
    case OscillatorKernel::baseline:
      return "x86-64 (SSE2) 4 lanes";
    case OscillatorKernel::avx2:
      return "x86-64-v3 (AVX2+FMA) 8 lanes";
    case OscillatorKernel::avx512:
      return "x86-64-v4 (AVX-512) 16 lanes";
  }
  return "unknown";
}

bool cpuRunsOscillatorKernel(OscillatorKernel kernel) {
  // The features of the levels the kernels are compiled for (target attributes in
  // oscillator_bank.cpp): x86-64-v3 = AVX2 + FMA + BMI2 (and older), x86-64-v4 = AVX-512 F, BW,
  // DQ, VL. Named by feature, not by level, so that clang (the fuzz build) accepts them too.
  __builtin_cpu_init();  // idempotent; needed only before static constructors have run
  switch (kernel) {
    case OscillatorKernel::baseline:
      return true;
    case OscillatorKernel::avx2:
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
             __builtin_cpu_supports("bmi2");
    case OscillatorKernel::avx512:
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
             __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
  }
  return false;
}

OscillatorKernel fastestOscillatorKernel() {
  if (cpuRunsOscillatorKernel(OscillatorKernel::avx512)) return OscillatorKernel::avx512;
  if (cpuRunsOscillatorKernel(OscillatorKernel::avx2)) return OscillatorKernel::avx2;
  return OscillatorKernel::baseline;
}

}  // namespace fluidsound::acoustics
