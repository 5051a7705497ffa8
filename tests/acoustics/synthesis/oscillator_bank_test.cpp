// Tests of acoustics/synthesis/oscillator_bank.h: every SIMD kernel the CPU runs, called explicitly, against
// the scalar reference (oscillator_bank_reference.h), over the shapes the synthesizer uses (1, 2
// and many listeners, full and masked groups, every count of active lanes).
#include "acoustics/synthesis/oscillator_bank.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "acoustics/synthesis/oscillator_bank_reference.h"
#include "acoustics/synthesis/oscillator_kernel.h"

namespace fluidsound::acoustics {
namespace {

/// A group as the synthesizer fills it: per lane an amplitude 10⁻³…1 Pa at a random phase, a
/// decay of 10…2000 /s and a frequency of 0.2…20 kHz at 48 kHz, a frequency change of up to 5 %
/// over the block, gains 0.1…2 changing by up to ±0.5 over the block; masked lanes start at a
/// random sample. Lanes from `activeLanes` on are zero, as the contract asks.
OscillatorGroup randomGroup(std::mt19937_64& random, int listeners, bool masked, int activeLanes) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr double kDt = 1.0 / 48000.0;
  OscillatorGroup g{};
  for (int lane = 0; lane < activeLanes; ++lane) {
    const double amplitude = std::pow(10.0, -3.0 * unit(random)),
                 phase = 2 * std::numbers::pi * unit(random);
    const double decay = 10.0 + 1990.0 * unit(random);
    const double w = 2 * std::numbers::pi * (200.0 + 19800.0 * unit(random));
    const double dw = 0.05 * w * (2 * unit(random) - 1) / kBlockSamples;
    g.zRe[lane] = static_cast<float>(amplitude * std::cos(phase));
    g.zIm[lane] = static_cast<float>(amplitude * std::sin(phase));
    g.rRe[lane] = static_cast<float>(std::exp(-decay * kDt) * std::cos(w * kDt));
    g.rIm[lane] = static_cast<float>(std::exp(-decay * kDt) * std::sin(w * kDt));
    g.cRe[lane] = static_cast<float>(std::cos(dw * kDt));
    g.cIm[lane] = static_cast<float>(std::sin(dw * kDt));
    g.firstSample[lane] =
        masked ? static_cast<float>(std::floor(unit(random) * kBlockSamples)) : 0.0f;
    for (int l = 0; l < listeners; ++l) {
      g.gain[l][lane] = static_cast<float>(0.1 + 1.9 * unit(random));
      g.gainStep[l][lane] = static_cast<float>((unit(random) - 0.5) / kBlockSamples);
    }
  }
  return g;
}

struct Shape {
  int listeners;
  bool masked;
  int activeLanes;
};

/// Every shape: listeners 1, 2 (fixed-count paths), 3 and 16 (the general path), full and
/// masked, 1 … 16 active lanes (each slice width and every tail).
std::vector<Shape> everyShape() {
  std::vector<Shape> shapes;
  for (const int listeners : {1, 2, 3, kMaxListeners})
    for (const bool masked : {false, true})
      for (int lanes = 1; lanes <= kOscillatorLanes; ++lanes)
        shapes.push_back({listeners, masked, lanes});
  return shapes;
}

std::string describe(const Shape& s) {
  return std::to_string(s.listeners) + " listener(s), " + (s.masked ? "masked" : "full") + ", " +
         std::to_string(s.activeLanes) + " lane(s)";
}

/// Two groups accumulated in turn (as the synthesizer does) into one accumulator.
std::vector<float> accumulateTwice(const OscillatorGroup& a, const OscillatorGroup& b,
                                   const Shape& s, std::optional<OscillatorKernel> kernel) {
  std::vector<float> acc(static_cast<std::size_t>(s.listeners) * kBlockSamples * kOscillatorLanes,
                         0.0f);
  for (const OscillatorGroup* g : {&a, &b}) {
    if (kernel)
      accumulateOscillatorGroup(*kernel, *g, s.listeners, s.masked, acc.data(), s.activeLanes);
    else
      accumulateOscillatorGroupReference(*g, s.listeners, s.masked, acc.data(), s.activeLanes);
  }
  return acc;
}

class EveryKernel : public ::testing::TestWithParam<OscillatorKernel> {
 protected:
  void SetUp() override {
    if (!cpuRunsOscillatorKernel(GetParam()))
      GTEST_SKIP() << "this CPU cannot run " << oscillatorKernelName(GetParam());
  }
};

// The kernel computes what the scalar reference computes. The baseline has no FMA and does the
// reference's operations in the reference's order per lane: the same bits. The AVX2 and AVX-512
// kernels fuse multiply-adds (one rounding fewer in z·r, r·c, the gain and gain·z + accumulator),
// which changes a lane by float rounding that the recurrence carries along the block: ≤ 512 steps
// of ~2⁻²⁴ each ≈ 3e-5 of the lane's scale A·g, the budget of the synthesizer's analytic test;
// allow 1e-4 as it does (measured 1.5e-5). A wrong operation errs by order 1.
TEST_P(EveryKernel, AgreesWithScalarReference) {
  const OscillatorKernel kernel = GetParam();
  std::mt19937_64 random(17);
  double worst = 0.0;
  for (const Shape& s : everyShape()) {
    const OscillatorGroup a = randomGroup(random, s.listeners, s.masked, s.activeLanes);
    const OscillatorGroup b = randomGroup(random, s.listeners, s.masked, s.activeLanes);
    const std::vector<float> got = accumulateTwice(a, b, s, kernel);
    const std::vector<float> expected = accumulateTwice(a, b, s, std::nullopt);
    if (kernel == OscillatorKernel::baseline) {
      ASSERT_EQ(0, std::memcmp(got.data(), expected.data(), got.size() * sizeof(float)))
          << describe(s);
      continue;
    }
    for (std::size_t i = 0; i < got.size(); ++i) {
      const int lane = static_cast<int>(i % kOscillatorLanes),
                l = static_cast<int>(i / (kBlockSamples * kOscillatorLanes));
      if (lane >= s.activeLanes) {
        ASSERT_EQ(got[i], 0.0f) << describe(s) << ": unused lane " << lane;
        continue;
      }
      // The lane's scale: |z| ≤ |z₀| (|r| ≤ 1), |gain| ≤ |g₀| + 512|step|, summed over both groups.
      double scale = 0.0;
      for (const OscillatorGroup* g : {&a, &b})
        scale += std::hypot(g->zRe[lane], g->zIm[lane]) *
                 (std::fabs(g->gain[l][lane]) + kBlockSamples * std::fabs(g->gainStep[l][lane]));
      const double error = std::fabs(double{got[i]} - double{expected[i]}) / scale;
      worst = std::max(worst, error);
      ASSERT_LT(error, 1e-4) << describe(s) << ", entry " << i;
    }
  }
  std::printf("%s: worst deviation from the reference %.3g of A·g\n",
              std::string(oscillatorKernelName(kernel)).c_str(), worst);
}

INSTANTIATE_TEST_SUITE_P(OscillatorBank, EveryKernel, ::testing::ValuesIn(kOscillatorKernels),
                         [](const auto& info) {
                           switch (info.param) {
                             case OscillatorKernel::baseline:
                               return std::string("Baseline");
                             case OscillatorKernel::avx2:
                               return std::string("Avx2");
                             case OscillatorKernel::avx512:
                               return std::string("Avx512");
                           }
                           return std::string("Unknown");
                         });

// The two fusing kernels fuse the same multiply-adds, so they agree bit for bit (what
// docs/synthesis.md promises: AVX2 and AVX-512 machines render the same file).
TEST(OscillatorBank, Avx2AndAvx512KernelsGiveSameBits) {
  for (const OscillatorKernel k : {OscillatorKernel::avx2, OscillatorKernel::avx512})
    if (!cpuRunsOscillatorKernel(k))
      GTEST_SKIP() << "this CPU cannot run " << oscillatorKernelName(k);
  std::mt19937_64 random(23);
  for (const Shape& s : everyShape()) {
    const OscillatorGroup a = randomGroup(random, s.listeners, s.masked, s.activeLanes);
    const OscillatorGroup b = randomGroup(random, s.listeners, s.masked, s.activeLanes);
    const std::vector<float> avx2 = accumulateTwice(a, b, s, OscillatorKernel::avx2);
    const std::vector<float> avx512 = accumulateTwice(a, b, s, OscillatorKernel::avx512);
    ASSERT_EQ(0, std::memcmp(avx2.data(), avx512.data(), avx2.size() * sizeof(float)))
        << describe(s);
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
