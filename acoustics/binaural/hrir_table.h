// acoustics/binaural/hrir_table.h — a head's measured impulse responses (an HRTF set such as the
// MIT KEMAR set, read from a SOFA file by io/hrir_file.h) as a record, and what a binaural
// listener needs of it: the measured direction nearest a source, the pair's interaural time and
// level differences, and a world direction in the head's frame. docs/binaural.md.
#pragma once

#include <cstddef>
#include <vector>

#include "sim/core/vec3.h"

namespace fluidsound::acoustics {

/// Head-related impulse responses, one pair per measured direction.
struct HrirTable {
  double sampleRate = 0.0;              ///< Hz
  /// Unit vectors from the head's centre to each measured source, in the head's frame: x ahead,
  /// y to the left ear, z up.
  std::vector<Vec3> directions;
  std::vector<std::vector<float>> left, right;  ///< per direction, the ears' impulse responses
  std::vector<double> delayLeft, delayRight;    ///< per direction, delays the responses leave out [s]
};

/// Index of the measured direction nearest `direction` (head frame, any length > 0).
std::size_t nearestDirection(const HrirTable& table, const Vec3& direction);

/// @brief Interaural time difference [s] of direction `index`: the lag that best aligns the right
///        ear's response with the left's (cross-correlation, refined by a parabola through the
///        peak), plus the difference of the delays; > 0 when the left ear hears first.
double interauralTimeDifference(const HrirTable& table, std::size_t index);

/// @brief Interaural level difference [dB] of direction `index` at `frequency` [Hz]:
///        20 log₁₀ |H_left(f)| / |H_right(f)|, each the response's Fourier sum at f.
double interauralLevelDifference(const HrirTable& table, std::size_t index, double frequency);

/// |H(f)|: the magnitude of `response`'s Fourier sum at `frequency` [Hz].
double responseMagnitude(const std::vector<float>& response, double frequency, double sampleRate);

/// @brief The gain that makes the set's responses pressure at the ear ÷ free-field pressure at the
///        head's centre: 1 / the mean of both ears' |H(f)| for the direction nearest straight ahead
///        over f = 200, 250, …, 500 Hz, where a head changes the sound by about 1 dB or less
///        (Shaw 1974; Kuhn 1977). A measured set also holds its loudspeaker's and microphones'
///        gains, which this removes.
/// @throws std::invalid_argument if those responses are silent
double freeFieldGain(const HrirTable& table);

/// @brief `world` in the frame of a head facing `facing` with `up` (need not be unit or exactly
///        perpendicular: up is made perpendicular to facing): (·facing, ·left, ·up), left = up × facing.
/// @throws std::invalid_argument when facing or up is zero or they are parallel
Vec3 headDirection(const Vec3& world, const Vec3& facing, const Vec3& up);

}  // namespace fluidsound::acoustics
