// acoustics/analysis/spectrum_statistics.cpp — spectral centroid and line prominence (see
// spectrum_statistics.h).
#include "acoustics/analysis/spectrum_statistics.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace fluidsound::acoustics {
namespace {

/// Bins either side of the line's bin searched for its peak: a line between bins k and k+1 peaks
/// in one of them.
constexpr std::ptrdiff_t kLineHalfWidthBins = 1;
/// Nearest neighbour counted, in bins: the Hann main lobe spans ±2 bins, so from 3 bins on the
/// neighbours hold the background, not the line's own lobe (its first sidelobe is −31 dB).
constexpr std::ptrdiff_t kNeighbourGuardBins = 3;
/// Fewest neighbouring bins whose median is a background level rather than one sample of it.
constexpr std::size_t kMinimumNeighbours = 4;

double median(std::vector<double> values) {
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower =
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

}  // namespace

double spectralCentroid(const PowerSpectrum& spectrum, const FrequencyBand& band) {
  double power = 0.0, moment = 0.0;
  std::size_t bins = 0;
  for (std::size_t k = 0; k < spectrum.power.size(); ++k) {
    const double f = spectrum.frequency(k);
    if (f < band.low || f > band.high) continue;
    power += spectrum.power[k];
    moment += f * spectrum.power[k];
    ++bins;
  }
  if (bins == 0 || !(power > 0.0))
    throw std::invalid_argument("spectralCentroid: expected power in the band " +
                                std::to_string(band.low) + " … " + std::to_string(band.high) +
                                " Hz, found " +
                                (bins == 0 ? std::string("no bin") : std::string("none")));
  return moment / power;
}

LineProminence lineProminence(const PowerSpectrum& spectrum, double frequency,
                              double neighbourhood) {
  const auto bins = static_cast<std::ptrdiff_t>(spectrum.power.size());
  const auto centre = static_cast<std::ptrdiff_t>(std::lround(frequency / spectrum.binWidth));
  const auto reach = static_cast<std::ptrdiff_t>(std::floor(neighbourhood / spectrum.binWidth));
  LineProminence line;
  line.frequency = frequency;
  for (std::ptrdiff_t k = centre - kLineHalfWidthBins; k <= centre + kLineHalfWidthBins; ++k)
    if (k >= 0 && k < bins)
      line.linePower = std::max(line.linePower, spectrum.power[static_cast<std::size_t>(k)]);
  std::vector<double> neighbours;
  for (std::ptrdiff_t d = kNeighbourGuardBins; d <= reach; ++d) {
    for (const std::ptrdiff_t k : {centre - d, centre + d})
      if (k > 0 && k < bins)
        neighbours.push_back(spectrum.power[static_cast<std::size_t>(k)]);  // never DC
  }
  if (neighbours.size() < kMinimumNeighbours)
    throw std::invalid_argument("lineProminence: expected at least 4 neighbouring bins around " +
                                std::to_string(frequency) + " Hz within " +
                                std::to_string(neighbourhood) + " Hz (bin width " +
                                std::to_string(spectrum.binWidth) + " Hz), found " +
                                std::to_string(neighbours.size()));
  line.neighbourPower = median(std::move(neighbours));
  // Silence everywhere is no line (0 dB); a line over an empty neighbourhood is +∞ dB.
  line.prominenceDecibels =
      line.linePower == 0.0 ? 0.0 : 10.0 * std::log10(line.linePower / line.neighbourPower);
  return line;
}

std::vector<LineProminence> harmonicLineProminences(const PowerSpectrum& spectrum, double rate,
                                                    int harmonics) {
  std::vector<LineProminence> lines;
  for (int k = 1; k <= harmonics; ++k)
    lines.push_back(lineProminence(spectrum, k * rate, 0.5 * rate));
  return lines;
}

double meanProminenceDecibels(const std::vector<LineProminence>& lines) {
  if (lines.empty())
    throw std::invalid_argument("meanProminenceDecibels: expected at least one line, found none");
  double sum = 0.0;
  for (const LineProminence& line : lines) sum += std::pow(10.0, line.prominenceDecibels / 10.0);
  return 10.0 * std::log10(sum / static_cast<double>(lines.size()));
}

}  // namespace fluidsound::acoustics
