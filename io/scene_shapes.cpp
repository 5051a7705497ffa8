// io/scene_shapes.cpp — the liquid regions, emitters and solids of a scene file (see
// scene_shapes.h).
#include "io/scene_shapes.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <system_error>
#include <vector>

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// "a, b and c" (or "a and b", or "a").
std::string joinWithAnd(const std::vector<std::string_view>& words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) out += (i + 1 == words.size()) ? " and " : ", ";
    out += words[i];
  }
  return out;
}

/// A mesh path, resolved against the scene file's folder; the file must open for reading.
sim::MeshFile meshFile(const JsonValidator& check, const json& value, const std::string& path,
                       const fs::path& folder) {
  const std::string expected =
      "the path of a readable mesh file (OBJ or PLY; relative to the scene file's folder)";
  const fs::path resolved =
      (folder / fs::path(check.nonEmptyText(value, path, expected))).lexically_normal();
  const std::string where = describe(value) + " (" + resolved.string() + ": ";
  std::error_code ec;
  if (!fs::exists(resolved, ec)) check.fail(path, expected, where + "no such file)");
  if (fs::is_directory(resolved, ec)) check.fail(path, expected, where + "a folder)");
  std::FILE* file = std::fopen(resolved.c_str(), "rb");
  if (file == nullptr) {
    check.fail(path, expected, where + std::generic_category().message(errno) + ")");
  }
  std::fclose(file);
  return sim::MeshFile{resolved};
}


/// A non-zero direction, returned normalised.
Vec3 unitDirection(const JsonValidator& check, const json& parent, const std::string& parentPath,
                   std::string_view key) {
  const Vec3 v = check.requiredVector(parent, parentPath, key, "a direction, any length");
  // Scaled by the largest component first, so tiny or huge inputs neither under- nor overflow.
  const double largest = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  if (!(largest > 0)) {
    check.fail(memberPath(parentPath, key), "a non-zero direction [x, y, z]", parent[key].dump());
  }
  const Vec3 scaled{v[0] / largest, v[1] / largest, v[2] / largest};
  const double length = std::hypot(scaled[0], scaled[1], scaled[2]);
  return {scaled[0] / length, scaled[1] / length, scaled[2] / length};
}

/// Key j of a solid's path; `earlier` holds keys 0 … j−1.
sim::PathKey pathKey(const JsonValidator& check, const json& value, const std::string& keysPath,
                     std::size_t j, const std::vector<sim::PathKey>& earlier) {
  const std::string path = elementPath(keysPath, j);
  check.requireObject(value, path, "an object with t (seconds) and translate (metres)");
  check.rejectUnknownKeys(value, path, {"t", "translate"});
  sim::PathKey key;
  key.time = check.requiredNumber(value, path, "t", "a number >= 0 (seconds)", nonNegative);
  if (j > 0 && !(key.time > earlier.back().time)) {
    check.fail(memberPath(path, "t"),
               "a time greater than path[" + std::to_string(j - 1) +
                   "].t = " + formatNumber(earlier.back().time) + " (keys in time order; seconds)",
               describe(value["t"]));
  }
  key.translate = check.requiredVector(value, path, "translate", "metres");
  return key;
}

/// A derived number for a message, to 6 significant digits.
std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

/// "[x, y, z]", each to 6 significant digits.
std::string vectorText(const Vec3& v) {
  std::string text = "[";
  for (std::size_t a = 0; a < 3; ++a) text.append(a > 0 ? ", " : "").append(shortNumber(v[a]));
  return text + "]";
}

/// The disk of an emitter against the domain: a radius beyond the domain's diagonal is no nozzle
/// of this domain (its particles grow as π r², clipped to the domain or not: a 7 m disk over a 4 cm
/// box of 1 cm cells draws 3·10⁷ of them in 0.05 s at 0.5 m/s), and a disk that lies wholly
/// outside the domain pours nothing into it. "Wholly
/// outside": its axis-aligned bounding box (half-width r √(1 − n_a²) along axis a) misses the
/// domain box on some axis (touching counts as meeting).
void requireDiskInDomain(const JsonValidator& check, const json& disk, const std::string& diskPath,
                         const sim::Emitter& e, const sim::Domain& domain) {
  Vec3 extent{};
  for (std::size_t a = 0; a < 3; ++a) extent[a] = domain.max[a] - domain.min[a];
  const double diagonal = std::hypot(extent[0], extent[1], extent[2]);
  if (!(e.radius <= diagonal)) {
    check.fail(
        memberPath(diskPath, "radius"),
        "a number > 0 and at most the domain's diagonal, " + shortNumber(diagonal) + " (metres)",
        describe(disk["radius"]));
  }
  for (std::size_t a = 0; a < 3; ++a) {
    const double halfWidth = e.radius * std::sqrt(std::max(0.0, 1.0 - e.normal[a] * e.normal[a]));
    if (e.center[a] + halfWidth >= domain.min[a] && e.center[a] - halfWidth <= domain.max[a])
      continue;
    check.fail(memberPath(diskPath, "center"),
               "a disk that meets the domain " + vectorText(domain.min) + " to " +
                   vectorText(domain.max) + " (metres; the disk of radius " +
                   shortNumber(e.radius) + " lies wholly outside it)",
               vectorText(e.center));
  }
}

}  // namespace

sim::Shape readShape(const JsonValidator& check, const json& item, const std::string& path,
                 const fs::path& folder) {
  std::vector<std::string_view> given;
  for (std::string_view key : {"box", "sphere", "mesh"}) {
    if (item.contains(key)) given.push_back(key);
  }
  if (given.size() != 1) {
    check.fail(path, "exactly one shape: box, sphere or mesh",
               given.empty() ? "none of them" : joinWithAnd(given));
  }
  const std::string shapePath = memberPath(path, given.front());
  const json& value = item[given.front()];
  if (given.front() == "box") {
    check.requireObject(value, shapePath, "an object with min and max (metres)");
    check.rejectUnknownKeys(value, shapePath, {"min", "max"});
    sim::Box box;
    box.min = check.requiredVector(value, shapePath, "min", "metres");
    box.max = check.requiredVector(value, shapePath, "max", "metres");
    requireOrdered(check, value, shapePath, box.min, box.max);
    return box;
  }
  if (given.front() == "sphere") {
    check.requireObject(value, shapePath, "an object with center and radius (metres)");
    check.rejectUnknownKeys(value, shapePath, {"center", "radius"});
    sim::Sphere sphere;
    sphere.center = check.requiredVector(value, shapePath, "center", "metres");
    sphere.radius =
        check.requiredNumber(value, shapePath, "radius", "a number > 0 (metres)", positive);
    return sphere;
  }
  return meshFile(check, value, shapePath, folder);
}

void requireOrdered(const JsonValidator& check, const json& box, const std::string& path,
                    const Vec3& min, const Vec3& max) {
  for (std::size_t a = 0; a < 3; ++a) {
    if (!(max[a] > min[a])) {
      check.fail(
          elementPath(memberPath(path, "max"), a),
          "a number > min[" + std::to_string(a) + "] = " + formatNumber(min[a]) + " (metres)",
          describe(box["max"][a]));
    }
  }
}

/// |velocity| of a liquid region and an emitter's speed [m/s]: two thirds of the speed of sound in
/// water (1480 m/s); far beyond it the incompressible model, and the scene, make no sense.
constexpr double kMaxLiquidSpeed = 1000.0;

sim::LiquidRegion readLiquidRegion(const JsonValidator& check, const json& item,
                                   const std::string& path, const fs::path& folder) {
  check.requireObject(item, path, "an object with one of box, sphere or mesh");
  check.rejectUnknownKeys(item, path, {"box", "sphere", "mesh", "velocity"});
  sim::LiquidRegion region;
  region.shape = readShape(check, item, path, folder);
  if (const json* velocity = findMember(item, "velocity")) {
    region.velocity = check.vector(*velocity, memberPath(path, "velocity"), "m/s");
    const Vec3& v = region.velocity;
    const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(speed <= kMaxLiquidSpeed)) {
      check.fail(memberPath(path, "velocity"), "a velocity of at most 1000 m/s (two thirds of the speed of sound in water)",
                 "|v| = " + formatNumber(speed) + " m/s");
    }
  }
  return region;
}

sim::Emitter readEmitter(const JsonValidator& check, const json& item, const std::string& path,
                         const sim::TimeSettings& time, const sim::Domain& domain) {
  check.requireObject(item, path, "an object with disk and speed");
  check.rejectUnknownKeys(item, path, {"disk", "speed", "start", "end"});
  sim::Emitter e;
  const json& disk =
      check.requiredObject(item, path, "disk", "an object with center, normal and radius");
  const std::string diskPath = memberPath(path, "disk");
  check.rejectUnknownKeys(disk, diskPath, {"center", "normal", "radius"});
  e.center = check.requiredVector(disk, diskPath, "center", "metres");
  e.normal = unitDirection(check, disk, diskPath, "normal");
  e.radius = check.requiredNumber(disk, diskPath, "radius", "a number > 0 (metres)", positive);
  requireDiskInDomain(check, disk, diskPath, e, domain);
  e.speed = check.requiredNumber(item, path, "speed",
                                 "a number > 0 and <= 1000 (m/s; two thirds of the speed of sound in water)",
                                 [](double v) { return v > 0 && v <= kMaxLiquidSpeed; });
  e.start = check.optionalNumber(item, path, "start", 0.0, "a number >= 0 (seconds)", nonNegative);
  if (const json* end = findMember(item, "end")) {
    e.end = check.number(*end, memberPath(path, "end"),
                         "a number > start = " + formatNumber(e.start) + " (seconds)",
                         [&](double v) { return v > e.start; });
  } else {
    e.end = time.duration;  // the default end
    if (!(e.end > e.start)) {
      check.fail(memberPath(path, "start"),
                 "a number < time.duration = " + formatNumber(time.duration) +
                     " (seconds; the default end)",
                 describe(item["start"]));
    }
  }
  return e;
}

void readPlacement(const JsonValidator& check, const json& item, const std::string& path, double& scale,
                   Vec3& translate, Vec3& rotateDegrees) {
  scale = check.optionalNumber(item, path, "scale", 1.0, "a number > 0 (scale factor)", positive);
  if (const json* offset = findMember(item, "translate"))
    translate = check.vector(*offset, memberPath(path, "translate"), "metres");
  if (const json* rotate = findMember(item, "rotate"))
    rotateDegrees = check.vector(*rotate, memberPath(path, "rotate"), "degrees about x, y, z");
}

sim::Solid readSolid(const JsonValidator& check, const json& item, const std::string& path,
                     const fs::path& folder) {
  check.requireObject(item, path, "an object with one of box, sphere or mesh");
  check.rejectUnknownKeys(item, path,
                          {"box", "sphere", "mesh", "scale", "translate", "rotate", "path"});
  sim::Solid s;
  s.shape = readShape(check, item, path, folder);
  readPlacement(check, item, path, s.scale, s.translate, s.rotateDegrees);
  if (const json* keys = check.optionalArray(
          item, path, "path", "an array of keys {t (seconds), translate (metres)}")) {
    const std::string keysPath = memberPath(path, "path");
    for (std::size_t j = 0; j < keys->size(); ++j)
      s.path.push_back(pathKey(check, (*keys)[j], keysPath, j, s.path));
  }
  return s;
}

}  // namespace fluidsound::io
