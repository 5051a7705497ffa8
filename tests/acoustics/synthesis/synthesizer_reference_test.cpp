// tests/acoustics/synthesis/synthesizer_reference_test.cpp — the renderer (packed lane records,
// parallel segments, SIMD kernel) gives the same samples, bit for bit, as the plain reference
// (unpacked lanes, one block after another, the scalar loop) on the baseline kernel, for 1, 2 and
// 3 listeners, 1 and 2 threads.
#include "acoustics/synthesis/synthesizer_reference.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/task_arena.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "acoustics/synthesis/oscillator_bank.h"
#include "acoustics/synthesis/oscillator_kernel.h"
#include "acoustics/synthesis/synthesizer.h"

namespace fluidsound::acoustics {
namespace {

constexpr double kSampleRate = 48000.0;

/// `count` bubbles over `span` seconds, rising with a changing transfer on `channels` listeners:
/// births anywhere, a few exactly on a block's first sample, many at once (more than a group of
/// 16 in a block), one too small to render below Nyquist, one born after `duration` [s].
BubbleTrackSet crowd(std::size_t channels, std::size_t count, double span, double duration) {
  BubbleTrackSet set;
  for (std::size_t l = 0; l < channels; ++l) set.listeners.emplace_back(1, 'a' + l);
  std::mt19937_64 random(18 + channels);
  const auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(random() >> 11) * 0x1p-53;
  };
  for (std::size_t i = 0; i < count; ++i) {
    BubbleTrack b;
    b.radius = std::exp(uniform(std::log(0.4e-3), std::log(4e-3)));
    b.birth = i % 7 == 0 ? std::floor(uniform(0.0, span) * kSampleRate / kBlockSamples) *
                               kBlockSamples / kSampleRate
                         : uniform(0.0, span);
    const double fromDepth = uniform(5e-3, 40e-3);
    for (int k = 0; k < 6; ++k) {
      TrackSample s;
      s.time = b.birth + k / 30.0;
      s.depth = fromDepth + (1.6 * b.radius - fromDepth) * k / 5.0;
      for (std::size_t l = 0; l < channels; ++l) s.transfer.push_back(uniform(0.2, 1.2));
      b.track.push_back(s);
    }
    set.bubbles.push_back(std::move(b));
  }
  set.bubbles.push_back({1e-6, 0.1, std::nullopt, {}});              // aliased: dropped
  set.bubbles.push_back({1e-3, duration + 0.01, std::nullopt, {}});  // silent: dropped
  return set;
}

TEST(SynthesizerReference, RendererGivesTheReferenceSamplesBitForBit) {
  // Claim: on the baseline kernel the renderer's samples equal the reference's bit for bit: the
  // packed records hold what the unpacked lanes hold, segments (0.34 s) and threads leave no
  // trace, and the lanes are summed in the same order. Reference: synthesizeReference.
  // Tolerance: none.
  for (const std::size_t channels : {1u, 2u, 3u}) {
    const BubbleTrackSet set = crowd(channels, 120, 1.0, 1.2);
    SynthesisSettings settings;
    settings.sampleRate = kSampleRate;
    settings.kernel = OscillatorKernel::baseline;
    settings.duration = 1.2;
    const std::vector<std::vector<float>> expected = synthesizeReference(set, settings);
    ASSERT_EQ(expected.size(), channels);
    for (const int threads : {1, 2}) {
      tbb::task_arena arena(threads);
      SynthesisResult fast;
      arena.execute([&] { fast = synthesize(set, settings); });
      ASSERT_EQ(fast.channels.size(), channels);
      EXPECT_EQ(fast.report.bubblesAboveNyquist, 1);
      EXPECT_EQ(fast.report.bubblesSilent, 1);
      for (std::size_t l = 0; l < channels; ++l) {
        ASSERT_EQ(fast.channels[l].size(), expected[l].size());
        std::size_t differing = 0, sounding = 0;
        for (std::size_t n = 0; n < expected[l].size(); ++n) {
          differing += std::bit_cast<std::uint32_t>(fast.channels[l][n]) !=
                       std::bit_cast<std::uint32_t>(expected[l][n]);
          sounding += expected[l][n] != 0.0f;
        }
        EXPECT_EQ(differing, 0u) << channels << " listeners, channel " << l << ", " << threads
                                 << " threads";
        EXPECT_GT(sounding, expected[l].size() / 2);
      }
    }
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
