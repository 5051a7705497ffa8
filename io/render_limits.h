// io/render_limits.h — the largest audio render fluidsound accepts (docs/cli.md, "Render size"):
// checked where the duration, sample rate and channel count are known, before anything is
// allocated (a bubble file's `duration: 1e9` used to end in std::bad_alloc).
#pragma once

#include <cstddef>
#include <cstdint>

namespace fluidsound::io {

/// Samples over all channels in one render: 2³¹, 8 GiB as 32-bit floats; 6.2 hours of stereo at
/// 48 kHz. A longer render is a typo, or a job to split into parts.
inline constexpr double kMaxRenderSamples = 2147483648.0;

/// Bytes held per rendered sample at the peak of `synth`: the 32-bit float channels and as much
/// again for the written copy (dither, normalisation, spectrogram) and headroom.
inline constexpr double kRenderBytesPerSample = 8.0;

/// duration × sample rate × channels, as a double (no overflow for any finite input).
inline double renderSamples(double seconds, double sampleRate, std::size_t channels) {
  return seconds * sampleRate * static_cast<double>(channels);
}

}  // namespace fluidsound::io
