// io/scene_bubbles.cpp — see scene_bubbles.h.
#include "io/scene_bubbles.h"

#include <limits>
#include <string>

#include "io/bubble_track_limits.h"
#include "io/input_error.h"

namespace fluidsound::io {
namespace {
using json = nlohmann::json;

/// Largest length in cells of a bubble-model setting (docs/bubbles.md measured 1 to 6).
constexpr double kMaxBubbleCells = 64;
/// Largest creation rate constant [1/s]: 500 times the default 20; bubbles scale in proportion
/// (1e308 drew an endless stream of attempts in the first frame).
constexpr double kMaxBubbleRate = 1e4;

/// min_radius < max_radius, named at the max; both within the radii a bubble-track file may hold
/// (io/bubble_track_limits.h), so that what `simulate` writes, `synth` reads.
void requireRadiusOrder(const JsonValidator& check, const std::string& path, double min, double max) {
  const std::string range = "a radius from 1e-06 to 1 (metres, the range of a bubble-track file)";
  static_assert(kMinBubbleRadius == 1e-6 && kMaxBubbleRadius == 1.0, "the text above names the bounds");
  if (!isBubbleRadius(min)) check.fail(memberPath(path, "min_radius"), range, formatNumber(min));
  if (!isBubbleRadius(max)) check.fail(memberPath(path, "max_radius"), range, formatNumber(max));
  if (!(max > min))
    check.fail(memberPath(path, "max_radius"), "a radius > min_radius = " + std::to_string(min) + " (metres)",
               std::to_string(max));
}

sim::BubbleSizeDistribution readSizes(const JsonValidator& check, const json& object, const std::string& path) {
  check.rejectUnknownKeys(object, path, {"power_law", "gaussian"});
  const json* power = findMember(object, "power_law");
  const json* gaussian = findMember(object, "gaussian");
  if ((power == nullptr) == (gaussian == nullptr))
    check.fail(path, "exactly one distribution: power_law or gaussian",
               power == nullptr ? "none of them" : "both");
  if (power != nullptr) {
    const std::string p = memberPath(path, "power_law");
    check.requireObject(*power, p, "an object with min_radius, max_radius, hinze_radius (metres)");
    check.rejectUnknownKeys(*power, p, {"min_radius", "max_radius", "hinze_radius"});
    sim::PowerLawBubbleSizes s;
    s.minRadius = check.optionalNumber(*power, p, "min_radius", s.minRadius, "a number > 0 (metres)", positive);
    s.maxRadius = check.optionalNumber(*power, p, "max_radius", s.maxRadius, "a number > 0 (metres)", positive);
    s.hinzeRadius = check.optionalNumber(*power, p, "hinze_radius", s.hinzeRadius, "a number > 0 (metres)", positive);
    requireRadiusOrder(check, p, s.minRadius, s.maxRadius);
    return s;
  }
  const std::string p = memberPath(path, "gaussian");
  check.requireObject(*gaussian, p, "an object with mean_radius and radius_deviation (metres)");
  check.rejectUnknownKeys(*gaussian, p, {"mean_radius", "radius_deviation", "min_radius", "max_radius"});
  sim::GaussianBubbleSizes s;
  s.meanRadius = check.requiredNumber(*gaussian, p, "mean_radius", "a number > 0 (metres)", positive);
  s.radiusDeviation = check.requiredNumber(*gaussian, p, "radius_deviation", "a number > 0 (metres)", positive);
  s.minRadius = check.optionalNumber(*gaussian, p, "min_radius", s.minRadius, "a number > 0 (metres)", positive);
  s.maxRadius = check.optionalNumber(*gaussian, p, "max_radius", s.maxRadius, "a number > 0 (metres)", positive);
  requireRadiusOrder(check, p, s.minRadius, s.maxRadius);
  return s;
}
}  // namespace

sim::BubbleSettings readBubbleSettings(const JsonValidator& check, const json& object) {
  const std::string path = "bubbles";
  check.rejectUnknownKeys(object, path,
                          {"band_cells", "entrainment_depth_cells", "entrainment_window", "entrainment_speed",
                           "probe_cells", "seed_lifetime", "potential_decay_time", "rate", "sizes", "jitter_cells",
                           "min_seeds", "neighbourhood_cells", "neighbourhood_radii"});
  sim::BubbleSettings s;
  // Lengths in cells: at most kMaxBubbleCells (a band or probe wider than that spans a grid, and
  // 1e308 cells overflowed the band's integer cell counts: a crash).
  const auto cells = [&](std::string_view key, double fallback) {
    return check.optionalNumber(object, path, key, fallback, "a number > 0 and <= 64 (cells)",
                                [](double v) { return v > 0 && v <= kMaxBubbleCells; });
  };
  const auto cellsOrZero = [&](std::string_view key, double fallback) {
    return check.optionalNumber(object, path, key, fallback, "a number >= 0 and <= 64 (cells)",
                                [](double v) { return v >= 0 && v <= kMaxBubbleCells; });
  };
  s.bandCells = cells("band_cells", s.bandCells);
  s.entrainmentDepthCells = cells("entrainment_depth_cells", s.entrainmentDepthCells);
  s.probeCells = cells("probe_cells", s.probeCells);
  s.entrainmentWindow =
      check.optionalNumber(object, path, "entrainment_window", s.entrainmentWindow, "a number > 0 (seconds)", positive);
  s.entrainmentSpeed =
      check.optionalNumber(object, path, "entrainment_speed", s.entrainmentSpeed, "a number > 0 (m/s)", positive);
  s.seedLifetime =
      check.optionalNumber(object, path, "seed_lifetime", s.seedLifetime, "a number > 0 (seconds)", positive);
  s.potentialDecayTime = check.optionalNumber(object, path, "potential_decay_time", s.potentialDecayTime,
                                              "a number > 0 (seconds)", positive);
  s.rate = check.optionalNumber(object, path, "rate", s.rate,
                                "a number >= 0 and <= 10000 (creation attempts per second per unit potential)",
                                [](double v) { return v >= 0 && v <= kMaxBubbleRate; });
  s.jitterCells = cellsOrZero("jitter_cells", s.jitterCells);
  if (const json* minSeeds = findMember(object, "min_seeds"))
    s.minSeeds = static_cast<int>(check.wholeNumber(*minSeeds, memberPath(path, "min_seeds"), "an integer from 1 to 1000", 1, 1000));
  s.neighbourhoodCells = cellsOrZero("neighbourhood_cells", s.neighbourhoodCells);
  s.neighbourhoodRadii = check.optionalNumber(object, path, "neighbourhood_radii", s.neighbourhoodRadii,
                                              "a number >= 0 (bubble radii)", nonNegative);
  if (const json* sizes = check.optionalObject(object, path, "sizes", "an object: power_law or gaussian"))
    s.sizes = readSizes(check, *sizes, memberPath(path, "sizes"));
  // Whatever the field checks above let through, the model's own check is the last word.
  try {
    sim::validateBubbleSettings(s);
  } catch (const std::invalid_argument& e) {
    check.fail(path, "bubble settings the model accepts", e.what());
  }
  return s;
}

}  // namespace fluidsound::io
