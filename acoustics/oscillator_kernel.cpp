// acoustics/oscillator_kernel.cpp — names of the oscillator kernels and which this CPU runs.
#include "acoustics/oscillator_kernel.h"

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
  // The level names are those the kernels are compiled for (target attributes in
  // oscillator_bank.cpp), so the test and the code generation cannot disagree.
  __builtin_cpu_init();  // idempotent; needed only before static constructors have run
  switch (kernel) {
    case OscillatorKernel::baseline:
      return true;
    case OscillatorKernel::avx2:
      return __builtin_cpu_supports("x86-64-v3");
    case OscillatorKernel::avx512:
      return __builtin_cpu_supports("x86-64-v4");
  }
  return false;
}

OscillatorKernel fastestOscillatorKernel() {
  if (cpuRunsOscillatorKernel(OscillatorKernel::avx512)) return OscillatorKernel::avx512;
  if (cpuRunsOscillatorKernel(OscillatorKernel::avx2)) return OscillatorKernel::avx2;
  return OscillatorKernel::baseline;
}

}  // namespace fluidsound::acoustics
