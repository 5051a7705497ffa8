// acoustics/synthesis/oscillator_bank.h — the audio-rate inner loop of synthesis: a group of damped complex
// oscillators advanced by an exact per-sample recurrence, z ← z·r, r ← r·c, summed with a linearly
// varying gain per listener. With r = e^{(−β + iω)Δt} and c = e^{iΔω·Δt}, the phase advances by
// ω_n·Δt with ω_n linear in n: the phase integrates the instantaneous frequency exactly at the
// samples (no explicit ODE step, so no numerical detuning or damping).
#pragma once

#include <cstddef>

#include "acoustics/bubble/bubble_track.h"  // kMaxListeners
#include "acoustics/synthesis/oscillator_kernel.h"

namespace fluidsound::acoustics {

/// Oscillators in one group: one AVX-512 register of floats; the AVX2 kernel runs a group as two
/// 8-lane halves, the baseline as four 4-lane quarters (oscillator_kernel.h).
inline constexpr int kOscillatorLanes = 16;

/// Samples in one synthesis block: per-frame values are interpolated to block boundaries and vary
/// linearly inside a block (10.7 ms at 48 kHz, a third of a 33 ms video frame; the linear pieces
/// follow the smooth track within ~0.1 % in frequency for a bubble rising to the surface). Longer
/// blocks spread the per-bubble cost of each block over more samples.
inline constexpr int kBlockSamples = 512;

/// The state of kOscillatorLanes oscillators over one block, structure-of-arrays.
/// A lane that is unused has zero amplitude and zero gain.
struct OscillatorGroup {
  alignas(64) float zRe[kOscillatorLanes];   ///< complex pressure state at the first sample [Pa]
  alignas(64) float zIm[kOscillatorLanes];
  alignas(64) float rRe[kOscillatorLanes];   ///< per-sample factor e^{(−β+iω)Δt} at the first sample
  alignas(64) float rIm[kOscillatorLanes];
  alignas(64) float cRe[kOscillatorLanes];   ///< per-sample change of r: e^{iΔω Δt}
  alignas(64) float cIm[kOscillatorLanes];
  alignas(64) float gain[kMaxListeners][kOscillatorLanes];       ///< transfer at the first sample [-]
  alignas(64) float gainStep[kMaxListeners][kOscillatorLanes];   ///< transfer change per sample [-]
  alignas(64) float firstSample[kOscillatorLanes];  ///< sample offset in the block where a lane starts (as float)
};

/// @brief Adds Σ_lanes gain·Im z to `accumulator` over one block.
/// @param kernel       instruction-set version; the CPU must run it (cpuRunsOscillatorKernel).
///                     Each lane's arithmetic is the same in every kernel except that the AVX2 and
///                     AVX-512 ones fuse multiply-adds (FMA): those two agree bit for bit, the
///                     baseline differs from them in the last bits.
/// @param group        oscillators; all lanes start at offset 0 unless `masked`
/// @param listeners    number of channels, 1 … kMaxListeners
/// @param masked       honour firstSample: a lane is silent and frozen before its first sample
/// @param accumulator  [listeners][kBlockSamples][kOscillatorLanes] floats, added to (lanes are
///                     summed later, in a fixed order, so results do not depend on threads)
/// @param activeLanes  lanes in use, counted from lane 0; a group with few runs on narrower vectors
void accumulateOscillatorGroup(OscillatorKernel kernel, const OscillatorGroup& group, int listeners,
                               bool masked, float* accumulator, int activeLanes = kOscillatorLanes);

/// @brief Sums the lanes of `accumulator` (as filled by accumulateOscillatorGroup) into
///        `output[l][0 … count)`, overwriting it, by a fixed pairwise tree (deterministic, and
///        short dependency chains instead of kOscillatorLanes sequential additions).
/// @param count        samples to write, ≤ kBlockSamples
/// @param activeLanes  lanes any group of the block used (the others hold zeros)
void sumOscillatorLanes(const float* accumulator, int listeners, int count, float* const* output,
                        int activeLanes = kOscillatorLanes);

}  // namespace fluidsound::acoustics
