// acoustics/modal/mode_compression.h — fewer modes for the same sound: modes closer in frequency
// than the ear can tell apart merged into one (after Raghuvanshi & Lin 2006, as the thesis §3.51
// does it), and a mode's part of one event ended once it has decayed below a fraction of the
// event's peak (thesis §3.52). docs/solids.md, Compression.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace fluidsound::acoustics {

/// @brief The smallest frequency difference [Hz] the ear tells apart near frequency f [Hz]:
///        Zwicker & Fastl's just-noticeable frequency modulation (Psychoacoustics, 3rd ed. 2007,
///        §7.2): 3.6 Hz below 500 Hz, 0.7 % of f above (shared solids.md §1.2; the thesis's
///        Fig. 3-3 approximates the same curve). Not a constant 1 Hz: that would leave 22 000
///        distinguishable bins over the audible range, where this leaves about 670.
double frequencyDiscriminationLimit(double frequency);

/// How the modes fall into groups that sound as one.
struct ModeGroups {
  /// group[i]: the group of mode i (0, 1, … in ascending frequency)
  std::vector<std::size_t> group;
  /// first[g]: the mode that leads group g, the lowest in it; its frequency and decay are the group's
  std::vector<std::size_t> first;
};

/// @brief Groups modes given in ascending frequency [Hz]: walking up, a mode joins the group of
///        the mode before when it lies within frequencyDiscriminationLimit(f_lead) of that group's
///        lead; so every mode of a group lies within the limit of the frequency the group sounds at.
///        A group sounds as one oscillator at its lead's frequency and decay; an impact gives it
///        the members' combined amplitude (modal_synthesis.h: energy-preserving, not the thesis's
///        sum of the shapes' columns, which cancels or doubles modes that beat: docs/solids.md).
/// @throws std::invalid_argument if the frequencies are not ascending or not finite
ModeGroups groupIndistinguishableModes(std::span<const double> frequencies);

/// @brief The time [s] after an event at which a mode of initial amplitude a and decay rate d
///        [1/s] falls below `threshold` × the event's peak amplitude: ln(a/(threshold·peak))/d,
///        0 if it starts below (the thesis's 1e-5, made relative to the event: about −100 dB).
double truncationTime(double amplitude, double decayRate, double eventPeak, double threshold = 1e-5);

}  // namespace fluidsound::acoustics
