// Tests of acoustics/synthesis/oscillator_kernel.h: the kernel the synthesizer picks is one this CPU runs,
// and the widest it runs.
#include "acoustics/synthesis/oscillator_kernel.h"

#include <gtest/gtest.h>

namespace fluidsound::acoustics {
namespace {

TEST(OscillatorKernel, FastestIsTheWidestThisCpuRuns) {
  const OscillatorKernel fastest = fastestOscillatorKernel();
  EXPECT_TRUE(cpuRunsOscillatorKernel(fastest)) << oscillatorKernelName(fastest);
  EXPECT_TRUE(cpuRunsOscillatorKernel(OscillatorKernel::baseline));  // every x86-64 has SSE2
  for (const OscillatorKernel k : kOscillatorKernels) {
    if (static_cast<int>(k) > static_cast<int>(fastest)) {
      EXPECT_FALSE(cpuRunsOscillatorKernel(k)) << oscillatorKernelName(k);
    }
  }
}

// A CPU that runs AVX-512 (x86-64-v4) runs AVX2 (x86-64-v3): each level includes the one below;
// and the AVX2 kernel is only called where the CPU has the AVX2 and FMA it is compiled with.
TEST(OscillatorKernel, LevelsAreNested) {
  if (cpuRunsOscillatorKernel(OscillatorKernel::avx512)) {
    EXPECT_TRUE(cpuRunsOscillatorKernel(OscillatorKernel::avx2));
  }
  if (cpuRunsOscillatorKernel(OscillatorKernel::avx2)) {
    EXPECT_TRUE(__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"));
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
