// acoustics/binaural/hrir_convolution.h — one ear's signal: a source signal convolved with the
// ear's impulse response, delayed by whole samples, added into the ear's output. The tuned version
// is FFT overlap-add (Eigen's FFT, kissfft); the reference is the direct sum it is tested against.
// docs/binaural.md.
#pragma once

#include <cstddef>
#include <span>

#include "acoustics/binaural/hrir_table.h"

namespace fluidsound::acoustics {

/// @brief out[n] += gain · Σ_k response[k] · signal[n − k − delay] for every n < out.size()
///        (signal and out of any lengths; the convolution's tail beyond out is dropped).
///        FFT overlap-add in blocks; equal to addConvolutionDirect within float rounding.
void addConvolution(std::span<const float> signal, std::span<const float> response, std::size_t delay,
                    double gain, std::span<double> out);

/// @brief A source heard from measured direction `direction` of `table`: `signal` (its pressure at
///        the head's centre [Pa], at table.sampleRate) convolved with both ears' responses, scaled
///        by `gain` (freeFieldGain(table)) and delayed by the set's delays (whole samples), added
///        into the ears' `left` and `right`.
void addHeardFrom(const HrirTable& table, std::size_t direction, std::span<const float> signal, double gain,
                  std::span<double> left, std::span<double> right);

/// @brief The same sum, term by term: the reference, O(signal × response).
void addConvolutionDirect(std::span<const float> signal, std::span<const float> response,
                          std::size_t delay, double gain, std::span<double> out);

}  // namespace fluidsound::acoustics
