// io/loudness.h — programme loudness of a render (ITU-R BS.1770-4 / EBU R 128, through
// libebur128): integrated loudness [LUFS] and true peak [dBTP], and the gain that brings a
// render to a loudness target under a true-peak ceiling (docs/audio.md, "Loudness").
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fluidsound::io {

/// What a loudness meter read. Full scale is 1.0 (a render in pascals: 1 Pa = 0 dBFS).
struct LoudnessMeasurement {
  /// Integrated (gated) loudness [LUFS]; none when no 400 ms block passes the gates (silence,
  /// a signal shorter than 0.4 s, or one below the −70 LUFS absolute gate throughout).
  std::optional<double> integratedLufs;
  /// Largest true peak over all channels [dBTP] (4× oversampled below 96 kHz, 2× below
  /// 192 kHz, the samples themselves above: libebur128); −∞ for silence.
  double truePeakDbtp = 0.0;
};

/// @brief A streaming BS.1770 meter over interleaved frames. Every channel is weighted 1 (as
///        BS.1770's front channels): listeners are points in the scene, not loudspeakers, so
///        none is a surround (weight 1.41) or an LFE channel (left out).
class LoudnessMeter {
 public:
  /// @param channels    ≥ 1 (libebur128 takes any number)
  /// @param sampleRate  [Hz], a whole number ≥ 1
  /// @throws std::invalid_argument on bad parameters, std::bad_alloc if libebur128 fails
  LoudnessMeter(std::size_t channels, double sampleRate);
  ~LoudnessMeter();
  LoudnessMeter(const LoudnessMeter&) = delete;
  LoudnessMeter& operator=(const LoudnessMeter&) = delete;

  /// @param interleaved  frames × channels samples, frame by frame (full scale 1.0)
  void addInterleaved(std::span<const float> interleaved);

  LoudnessMeasurement measurement() const;

 private:
  struct State;  // libebur128's meter, kept out of this header
  std::unique_ptr<State> state_;
  std::size_t channels_;
};

/// @brief Measures whole channels (all the same length) scaled by `gain`.
/// @throws std::invalid_argument for no channels, unequal lengths or a bad rate
LoudnessMeasurement measureLoudness(std::span<const std::vector<float>> channels, double sampleRate,
                                    double gain = 1.0);

/// A loudness normalisation request (EBU R 128: −23 LUFS, true peak at most −1 dBTP).
struct LoudnessTarget {
  double integratedLufs = -23.0;      ///< target integrated loudness [LUFS]
  double truePeakCeilingDbtp = -1.0;  ///< the true peak may not exceed this [dBTP]
};

/// The gain that meets a LoudnessTarget.
struct LoudnessGain {
  double gainDecibels = 0.0;       ///< [dB] applied to the measured signal
  bool limitedByTruePeak = false;  ///< the target's gain would have put the true peak above the
                                   ///< ceiling, so the gain was lowered to just meet the ceiling
};

/// @brief Gain bringing `measured` to `target.integratedLufs`, lowered if needed so that the true
///        peak stays at or below the ceiling. Loudness and true peak both scale as 20·log10(gain)
///        (BS.1770's gates are relative except the −70 LUFS absolute one, which the caller avoids
///        by measuring near full scale).
/// @return none if the signal has no integrated loudness (silence or shorter than 0.4 s)
std::optional<LoudnessGain> loudnessNormalisationGain(const LoudnessMeasurement& measured,
                                                      const LoudnessTarget& target);

/// "1.2.6": the version of the libebur128 that runs (its own ebur128_get_version).
std::string loudnessLibraryVersion();

}  // namespace fluidsound::io
