// acoustics/analysis/spectrum_statistics.h — numbers read off a power spectrum (power_spectrum.h): where its
// energy sits (spectral centroid) and whether a line stands out of its neighbourhood (the
// frame-rate check of issue 6). docs/synthesis.md, "What the spectrum shows".
#pragma once

#include <vector>

#include "acoustics/analysis/power_spectrum.h"

namespace fluidsound::acoustics {

/// A frequency band [low, high] [Hz].
struct FrequencyBand {
  double low = 0.0;   ///< [Hz], ≥ 0
  double high = 0.0;  ///< [Hz], > low
};

/// @brief Spectral centroid Σ f_k P_k / Σ P_k [Hz] over the bins whose centre lies in `band`: the
///        power-weighted mean frequency (e.g. Peeters 2004, "A large set of audio features", §6.1).
/// @throws std::invalid_argument if the band holds no bin or no power
double spectralCentroid(const PowerSpectrum& spectrum, const FrequencyBand& band);

/// How far a line stands out of the spectrum around it.
struct LineProminence {
  double frequency = 0.0;           ///< where the line was looked for [Hz]
  double linePower = 0.0;           ///< largest density within ±1 bin of it [unit²/Hz]
  double neighbourPower = 0.0;      ///< median density of the neighbouring bins [unit²/Hz]
  double prominenceDecibels = 0.0;  ///< 10 log₁₀(linePower / neighbourPower) [dB]
};

/// @brief Prominence of a spectral line at `frequency`: the largest bin within ±1 bin (a line
///        between two bins loses at most 1.42 dB to the Hann window's scalloping) against the
///        median of the bins whose distance from it lies in [3 bins, neighbourhood] (3 bins clears
///        the Hann main lobe, ±2 bins). The median ignores a few outliers in the neighbourhood
///        (another line, a noise peak); a smooth slope across the neighbourhood moves it little.
/// @param neighbourhood  half-width of the neighbourhood [Hz]; for lines at the harmonics of F,
///                       F/2 keeps the neighbours between two harmonics
/// @throws std::invalid_argument if fewer than 4 neighbouring bins exist (neighbourhood too
///         narrow for the bin width, or the line too close to 0 Hz or Nyquist)
LineProminence lineProminence(const PowerSpectrum& spectrum, double frequency,
                              double neighbourhood);

/// @brief lineProminence at k·rate, k = 1 … harmonics, each with neighbourhood rate/2: the lines a
///        process repeating `rate` times a second would leave (a frame rate, in frames/s = Hz).
std::vector<LineProminence> harmonicLineProminences(const PowerSpectrum& spectrum, double rate,
                                                    int harmonics);

/// @brief The lines' mean prominence, 10 log₁₀ of the mean of linePower/neighbourPower [dB]: a
///        comb of lines each a little above the background — what a process repeating at a frame
///        rate leaves at every harmonic — shows here when no single line stands out, as averaging
///        K ratios shrinks the background's scatter by ~√K (on noise alone: ≈ +1.8 dB, since the
///        line is the largest of three bins and the reference a median).
/// @throws std::invalid_argument for no lines
double meanProminenceDecibels(const std::vector<LineProminence>& lines);

}  // namespace fluidsound::acoustics
