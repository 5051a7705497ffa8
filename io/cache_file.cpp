// io/cache_file.cpp — see cache_file.h.
#include "io/cache_file.h"

#include <algorithm>
#include <array>

#include <nlohmann/json.hpp>

#include "io/input_error.h"
#include "io/json_validation.h"
#include "io/scene_file.h"

namespace fluidsound::io {
namespace {

using nlohmann::json;

constexpr std::string_view kFormatTag = "fluidsound.cache/1";
constexpr KeyRules kCacheKeyRules{};
/// The keys a cache shares with a scene, read by the scene's rules.
constexpr std::string_view kSceneKeys[] = {"solids", "listeners", "audio", "bubbles", "transfer", "seed"};

/// A grid name, or a list of them tried in order.
std::vector<std::string> gridNames(const JsonValidator& check, const json& value, const std::string& path) {
  const std::string expected = "a grid name or an array of grid names (non-empty strings)";
  std::vector<std::string> names;
  if (value.is_string()) {
    names.push_back(check.nonEmptyText(value, path, expected));
  } else if (value.is_array() && !value.empty()) {
    for (std::size_t i = 0; i < value.size(); ++i) names.push_back(check.nonEmptyText(value[i], elementPath(path, i), expected));
  } else {
    check.fail(path, expected, describe(value));
  }
  return names;
}

/// `container.open`: face names, each once.
std::array<bool, 6> containerOpenFaces(const JsonValidator& check, const json& value) {
  constexpr std::array<std::string_view, 6> kFaces = {"-x", "+x", "-y", "+y", "-z", "+z"};
  const std::string expected = R"(an array of face names from "-x", "+x", "-y", "+y", "-z", "+z", each once)";
  if (!value.is_array()) check.fail("container.open", expected, describe(value));
  std::array<bool, 6> open{};
  for (std::size_t i = 0; i < value.size(); ++i) {
    const auto face = value[i].is_string() ? std::find(kFaces.begin(), kFaces.end(), value[i].get<std::string>())
                                           : kFaces.end();
    if (face == kFaces.end() || open[face - kFaces.begin()])
      check.fail(elementPath("container.open", i), expected, describe(value[i]));
    open[face - kFaces.begin()] = true;
  }
  return open;
}

}  // namespace

CacheDescription parseCacheFile(std::string_view text, const std::filesystem::path& file) {
  const std::string name = file.string();
  const json root = parseJson(text, name, DuplicateKeys::Rejected);
  const JsonValidator check(name, kCacheKeyRules);
  check.requireFormat(root, kFormatTag);
  check.rejectUnknownKeys(root, "", {"format", "frames", "fps", "grids", "units", "particles", "container", "solids",
                                     "listeners", "audio", "bubbles", "transfer", "seed"});
  CacheDescription cache;
  cache.file = file;
  const std::string framesExpected =
      "a frame pattern such as \"frames/%04d.vdb\", \"geo/surface.$F4.vdb\" or a folder (string)";
  const json* frames = findMember(root, "frames");
  if (frames == nullptr) check.fail("frames", framesExpected, std::string(kMissing));
  cache.frames = check.nonEmptyText(*frames, "frames", framesExpected);
  cache.fps = check.requiredNumber(root, "", "fps", "a number > 0 and <= 1000 (frames per second)",
                                   [](double v) { return v > 0.0 && v <= 1000.0; });
  if (const json* grids = check.optionalObject(root, "", "grids", "an object with surface and velocity")) {
    check.rejectUnknownKeys(*grids, "grids", {"surface", "velocity"});
    if (const json* s = findMember(*grids, "surface")) cache.grids.surface = gridNames(check, *s, "grids.surface");
    if (const json* v = findMember(*grids, "velocity")) cache.grids.velocity = gridNames(check, *v, "grids.velocity");
  }
  if (const json* units = check.optionalObject(root, "", "units", "an object with metres_per_unit and up")) {
    check.rejectUnknownKeys(*units, "units", {"metres_per_unit", "up"});
    cache.metresPerUnit = check.optionalNumber(*units, "units", "metres_per_unit", 1.0,
                                               "a number > 0 and <= 1000 (metres per unit: 0.01 for centimetres)",
                                               [](double v) { return v > 0.0 && v <= 1000.0; });
    if (const json* up = findMember(*units, "up")) {
      const std::string& axis = check.text(*up, "units.up", R"("y" (Houdini, fluidsound) or "z" (Blender))");
      if (axis != "y" && axis != "z") check.fail("units.up", R"("y" (Houdini, fluidsound) or "z" (Blender))", describe(*up));
      cache.up = axis == "z" ? UpAxis::Z : UpAxis::Y;
    }
  }
  if (const json* box = check.optionalObject(root, "", "container", "an object with min, max and open")) {
    check.rejectUnknownKeys(*box, "container", {"min", "max", "open"});
    Container c;
    c.min = check.requiredVector(*box, "container", "min", "metres");
    c.max = check.requiredVector(*box, "container", "max", "metres");
    for (int a = 0; a < 3; ++a)
      if (!(c.max[a] > c.min[a]))
        check.fail("container.max", "a corner above container.min on every axis", describe((*box)["max"]));
    if (const json* open = findMember(*box, "open")) c.open = containerOpenFaces(check, *open);
    cache.container = c;
  }
  if (const json* particles = findMember(root, "particles"))
    cache.particles = check.nonEmptyText(*particles, "particles", "a particle file pattern (OpenVDB points files; string)");

  // The sound part, by the scene's own rules and messages: the same keys in a scene document whose
  // domain and time stand in until the frames give them.
  json scene = {{"format", "fluidsound.scene/1"},
                {"domain", {{"min", {0, 0, 0}}, {"max", {1, 1, 1}}, {"cell", 0.1}}},
                {"time", {{"duration", 1.0}}}};
  for (std::string_view key : kSceneKeys)
    if (const json* value = findMember(root, key)) scene[std::string(key)] = *value;
  cache.defaultListener = findMember(root, "listeners") == nullptr;
  cache.scene = parseScene(scene.dump(), file);
  if (cache.defaultListener) cache.scene.listeners.clear();
  return cache;
}

CacheDescription readCacheFile(const std::filesystem::path& file) {
  return parseCacheFile(readInputFile(file), file);
}

}  // namespace fluidsound::io
