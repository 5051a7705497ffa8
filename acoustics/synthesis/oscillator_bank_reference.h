// acoustics/synthesis/oscillator_bank_reference.h — the oscillator inner loop written plainly, one lane and
// one sample at a time, in float: the specification the SIMD kernels of oscillator_bank.h are
// tested against (tests/acoustics/synthesis/oscillator_bank_test.cpp). Not used for rendering.
#pragma once

#include "acoustics/synthesis/oscillator_bank.h"

namespace fluidsound::acoustics {

/// @brief What accumulateOscillatorGroup computes, lane by lane and without fused multiply-adds
///        (its file is built with -ffp-contract=off): the baseline kernel's bits exactly, the
///        fusing kernels' within float rounding.
/// @param group, listeners, masked, accumulator, activeLanes  as accumulateOscillatorGroup
void accumulateOscillatorGroupReference(const OscillatorGroup& group, int listeners, bool masked,
                                        float* accumulator, int activeLanes = kOscillatorLanes);

}  // namespace fluidsound::acoustics
