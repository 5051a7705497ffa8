// io/scene_file.cpp — `fluidsound.scene/1` (docs/scene.md): JSON through nlohmann-json,
// validated field by field into sim::Scene; the liquid, emitters and solids in scene_shapes.cpp.
#include "io/scene_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "acoustics/bubble/bubble_track.h"
#include "io/hrir_file.h"
#include "io/input_error.h"
#include "io/json_validation.h"
#include "io/render_limits.h"
#include "io/scene_bubbles.h"
#include "io/scene_shapes.h"
#include "io/scene_bodies.h"
#include "io/scene_transfer.h"
#include "sim/fluid/fluid_scene.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr std::string_view kFormatTag = "fluidsound.scene/1";

/// A scene has no extension keys (a typo must not pass); unknown-key errors say "found an
/// unknown key" and also suggest a known key sharing the first 4 characters.
constexpr KeyRules kSceneKeyRules{
    .allowExtensionKeys = false, .matchSharedStart = true, .unknownKeyFound = "an unknown key"};

/// Each domain extent must be a whole number of cells to this relative tolerance: decimal
/// inputs are not exact in binary (0.4 / 0.008 = 50.000000000000007).
constexpr double kWholeCellTolerance = 1e-6;
/// Cells per axis: at least 2 (an interior for the pressure solve); at most 1024 (a dense
/// 1024³ grid already needs tens of GB; a larger count is a typo in `cell`).
constexpr double kMinCellsPerAxis = 2;
constexpr double kMaxCellsPerAxis = 1024;
/// Output sample rates [Hz]: the range of `fluidsound synth --rate` (docs/cli.md).
constexpr std::uint64_t kMinSampleRate = 8000;
constexpr std::uint64_t kMaxSampleRate = 768000;
/// Loosest relative residual for the pressure solve: beyond it the liquid visibly loses volume.
constexpr double kMaxPressureTolerance = 1e-2;
constexpr std::uint64_t kMaxParticlesPerCell = 64;
/// Height of the default listener above the domain centre [m] (DESIGN.md).
constexpr double kDefaultListenerHeight = 0.5;
/// Output frames a scene may ask for (duration × fps): 9 h at 30 fps; far beyond a shot, and
/// frame numbers stay well inside an int.
constexpr int kMaxFrames = 1000000;
/// Frames per second: a frame every millisecond at most. The frames are the liquid's state for the
/// bubble tracker and for the eye, not audio (synthesis runs at audio.sample_rate between them);
/// 44 100 fps asked for a whole VDB and PLY frame every 23 µs (4410 frames for 0.1 s of a 4 cm
/// tank, minutes of work for nothing the sound can use).
constexpr double kMaxFps = 1000.0;

/// Largest |gravity| [m/s²]: 100 g, beyond any centrifuge a liquid sound would be recorded in.
constexpr double kMaxGravity = 1000.0;

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/// Face names in the order of sim::Domain::open.
constexpr std::array<std::string_view, 6> kFaceNames = {"-x", "+x", "-y", "+y", "-z", "+z"};
constexpr std::array<std::string_view, 3> kAxisNames = {"x", "y", "z"};

/// A number rounded to `digits` significant digits, for derived values in messages.
std::string roundedNumber(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

/// The rules of `domain.cell` (docs/scene.md), shared by the parser and the `--cell` override:
/// > 0, 2 … 1024 cells per axis, each extent a whole number of cells (within
/// kWholeCellTolerance). `cellText` is the cell size as the input wrote it; `fail(expected,
/// found)` reports the first rule broken and must not return.
template <class Fail>
void requireValidCellSize(const sim::Domain& d, const std::string& cellText, const Fail& fail) {
  if (!(d.cell > 0.0) || !std::isfinite(d.cell)) fail("a number > 0 (metres)", cellText);
  for (std::size_t a = 0; a < 3; ++a) {
    const double cells = (d.max[a] - d.min[a]) / d.cell;
    if (!(cells >= kMinCellsPerAxis - 0.5 && cells < kMaxCellsPerAxis + 0.5)) {
      fail("a cell size (metres) giving 2 to 1024 cells per axis",
           cellText + " (" + roundedNumber(cells, 6) + (cells == 1 ? " cell" : " cells") +
               " along " + std::string(kAxisNames[a]) + ")");
    }
  }
  for (std::size_t a = 0; a < 3; ++a) {
    const double extent = d.max[a] - d.min[a];
    const double cells = extent / d.cell;
    const double nearest = std::round(cells);
    if (std::abs(cells - nearest) > kWholeCellTolerance * nearest) {
      fail("a cell size (metres) that divides the extent along " + std::string(kAxisNames[a]) +
               " (" + formatNumber(extent) + " m) into a whole number of cells, such as " +
               roundedNumber(extent / nearest, 10) + " (" + roundedNumber(nearest, 10) + " cells)",
           cellText + " (" + roundedNumber(cells, 6) + " cells)");
    }
  }
}

// ---- the validating reader ----------------------------------------------------------------------

/// Turns a parsed JSON document into a sim::Scene, or throws InputError at the first problem.
class SceneReader {
 public:
  SceneReader(const std::string& fileName, fs::path folder)
      : check_(fileName, kSceneKeyRules), folder_(std::move(folder)) {}

  sim::Scene read(const json& root) const {
    check_.requireFormat(root, kFormatTag);
    check_.rejectUnknownKeys(root, "",
                             {"format", "domain", "gravity", "time", "seed", "liquid", "emitters",
                              "solids", "bodies", "collision_samples", "listeners", "audio", "solver", "bubbles",
                              "transfer"});

    sim::Scene scene;
    scene.domain =
        domain(check_.requiredObject(root, "", "domain", "an object with min, max and cell"));
    if (const json* gravity = findMember(root, "gravity")) {
      scene.gravity = check_.vector(*gravity, "gravity", "m/s^2");
      if (!(norm(scene.gravity) <= kMaxGravity)) {
        check_.fail("gravity", "an acceleration of at most 1000 m/s^2 (about 100 g)",
                    "|g| = " + roundedNumber(norm(scene.gravity), 6) + " m/s^2");
      }
    }
    scene.time = time(check_.requiredObject(root, "", "time", "an object with duration (seconds)"));
    if (const json* seed = findMember(root, "seed")) {
      scene.seed = check_.wholeNumber(*seed, "seed", "an integer >= 0", 0,
                                      std::numeric_limits<std::uint64_t>::max());
    }
    if (const json* items =
            check_.optionalArray(root, "", "liquid", "an array of liquid regions")) {
      for (std::size_t i = 0; i < items->size(); ++i) {
        scene.liquid.push_back(
            readLiquidRegion(check_, (*items)[i], elementPath("liquid", i), folder_));
      }
    }
    if (const json* items = check_.optionalArray(root, "", "emitters", "an array of emitters")) {
      for (std::size_t i = 0; i < items->size(); ++i) {
        scene.emitters.push_back(
            readEmitter(check_, (*items)[i], elementPath("emitters", i), scene.time, scene.domain));
      }
    }
    if (const json* items = check_.optionalArray(root, "", "solids", "an array of solids")) {
      for (std::size_t i = 0; i < items->size(); ++i)
        scene.solids.push_back(readSolid(check_, (*items)[i], elementPath("solids", i), folder_));
    }
    if (const json* items = check_.optionalArray(root, "", "bodies", "an array of bodies")) {
      for (std::size_t i = 0; i < items->size(); ++i)
        scene.bodies.push_back(readSceneBody(check_, (*items)[i], elementPath("bodies", i), folder_, i));
    }
    if (const json* items = check_.optionalArray(root, "", "collision_samples",
                                                 "an array of recorded collision sounds per pair of materials")) {
      for (std::size_t i = 0; i < items->size(); ++i)
        scene.collisionSamples.push_back(
            readCollisionSamples(check_, (*items)[i], elementPath("collision_samples", i), folder_));
    }
    scene.listeners = listeners(root, scene.domain, scene.gravity);
    if (const json* audio =
            check_.optionalObject(root, "", "audio", "an object with sample_rate (Hz)")) {
      check_.rejectUnknownKeys(*audio, "audio", {"sample_rate", "hrtf"});
      if (const json* rate = findMember(*audio, "sample_rate")) {
        scene.sampleRate = static_cast<double>(
            check_.wholeNumber(*rate, "audio.sample_rate", "an integer from 8000 to 768000 (Hz)",
                               kMinSampleRate, kMaxSampleRate));
      }
      if (const json* hrtf = findMember(*audio, "hrtf")) scene.hrtf = hrtfFile(*hrtf);
    }
    requireDefaultHrtf(scene);
    if (const json* solver =
            check_.optionalObject(root, "", "solver", "an object of solver settings"))
      scene.solver = solverSettings(*solver);
    if (const json* bubbles =
            check_.optionalObject(root, "", "bubbles", "an object of bubble-model settings (docs/bubbles.md)"))
      scene.bubbles = readBubbleSettings(check_, *bubbles);
    if (const json* transfer = check_.optionalObject(
            root, "", "transfer", "an object of transfer-model settings (docs/transfer.md)"))
      scene.transfer = readTransferSettings(check_, *transfer);
    requireRenderableLength(scene);
    requireSubstepBudget(scene);
    return scene;
  }

 private:
  // ---- domain, time ----------------------------------------------------------------------------

  sim::Domain domain(const json& object) const {
    const std::string path = "domain";
    check_.rejectUnknownKeys(object, path, {"min", "max", "cell", "open"});
    sim::Domain d;
    d.min = check_.requiredVector(object, path, "min", "metres");
    d.max = check_.requiredVector(object, path, "max", "metres");
    requireOrdered(check_, object, path, d.min, d.max);
    d.cell = check_.requiredNumber(object, path, "cell", "a number > 0 (metres)", positive);
    requireValidCellSize(d, describe(object["cell"]),
                         [&](const std::string& expected, const std::string& found) {
                           check_.fail(memberPath(path, "cell"), expected, found);
                         });
    if (const json* open = findMember(object, "open")) d.open = openFaces(*open, "domain.open");
    return d;
  }

  std::array<bool, 6> openFaces(const json& value, const std::string& path) const {
    std::string names;
    for (std::string_view face : kFaceNames)
      names += (names.empty() ? "" : ", ") + quotedText(face);
    if (!value.is_array())
      check_.fail(path, "an array of face names from " + names, describe(value));
    std::array<bool, 6> open{};
    std::array<std::size_t, 6> listedAt{};
    for (std::size_t i = 0; i < value.size(); ++i) {
      const json& item = value[i];
      const std::string itemPath = elementPath(path, i);
      if (!item.is_string()) check_.fail(itemPath, "one of " + names, describe(item));
      const auto face = std::find(kFaceNames.begin(), kFaceNames.end(), item.get<std::string>());
      if (face == kFaceNames.end()) check_.fail(itemPath, "one of " + names, describe(item));
      const auto f = static_cast<std::size_t>(face - kFaceNames.begin());
      if (open[f]) {
        check_.fail(itemPath,
                    "a face not listed before (" + elementPath(path, listedAt[f]) + " is " +
                        quotedText(*face) + ")",
                    describe(item));
      }
      open[f] = true;
      listedAt[f] = i;
    }
    return open;
  }

  sim::TimeSettings time(const json& object) const {
    const std::string path = "time";
    check_.rejectUnknownKeys(object, path, {"duration", "fps", "cfl"});
    sim::TimeSettings t;
    t.duration =
        check_.requiredNumber(object, path, "duration", "a number > 0 (seconds)", positive);
    t.fps = check_.optionalNumber(object, path, "fps", t.fps,
                                  "a number > 0 and <= 1000 (frames per second)",
                                  [](double v) { return v > 0 && v <= kMaxFps; });
    t.cfl = check_.optionalNumber(object, path, "cfl", t.cfl, "a number > 0 (cells per substep)",
                                  positive);
    const double frames = t.duration * t.fps;
    if (!(frames <= kMaxFrames))
      check_.fail(path, "duration × fps ≤ " + std::to_string(kMaxFrames) + " frames",
                  roundedNumber(frames, 6) + " frames");
    return t;
  }

  /// The audio of the whole scene (duration × audio.sample_rate × listeners) within
  /// io::kMaxRenderSamples, named at time.duration (the machine's memory is checked by `run`).
  void requireRenderableLength(const sim::Scene& scene) const {
    std::size_t channels = 0;  // one per listener, two per head
    for (const sim::Listener& l : scene.listeners) channels += l.head ? 2 : 1;
    const double samples = renderSamples(scene.time.duration, scene.sampleRate, channels);
    if (samples <= kMaxRenderSamples) return;
    check_.fail("time.duration",
                "a duration whose audio (duration × audio.sample_rate × channels) is at most 2^31 samples",
                roundedNumber(scene.time.duration, 6) + " s × " + roundedNumber(scene.sampleRate, 6) + " Hz × " +
                    std::to_string(channels) + " = " + roundedNumber(samples, 4) + " samples");
  }

  /// The substeps a frame can need, from the fastest speed the scene can produce: its fastest
  /// source (an emitter's speed or a region's initial velocity) plus the free fall across the domain
  /// (√(2|g|L), L its diagonal) plus the solver's own gravity margin √(5h|g|) (stableTimeStep), over
  /// the distance allowed per substep (cfl × cell) and per frame (1 / fps). Above
  /// sim::kMaxSubstepsPerFrame a frame would (nearly) never end: refused, naming the likely field.
  void requireSubstepBudget(const sim::Scene& scene) const {
    const sim::TimeSettings& t = scene.time;
    const double h = scene.domain.cell, g = norm(scene.gravity);
    double source = 0.0;
    std::string sourceField;
    for (std::size_t e = 0; e < scene.emitters.size(); ++e)
      if (scene.emitters[e].speed > source)
        source = scene.emitters[e].speed, sourceField = memberPath(elementPath("emitters", e), "speed");
    for (std::size_t i = 0; i < scene.liquid.size(); ++i)
      if (norm(scene.liquid[i].velocity) > source)
        source = norm(scene.liquid[i].velocity), sourceField = memberPath(elementPath("liquid", i), "velocity");
    Vec3 diagonal{};
    for (std::size_t a = 0; a < 3; ++a) diagonal[a] = scene.domain.max[a] - scene.domain.min[a];
    const double fall = std::sqrt(2.0 * g * norm(diagonal)) + std::sqrt(5.0 * h * g);
    const auto substeps = [&](double cfl, double fps) { return (source + fall) / (cfl * h * fps); };
    const double limit = sim::kMaxSubstepsPerFrame;
    if (substeps(t.cfl, t.fps) <= limit) return;
    const sim::TimeSettings defaults;
    std::string field = source > fall ? sourceField : "gravity";
    if (substeps(defaults.cfl, t.fps) <= limit) field = "time.cfl";
    else if (substeps(t.cfl, defaults.fps) <= limit) field = "time.fps";
    check_.fail(field,
                "at most " + std::to_string(sim::kMaxSubstepsPerFrame) +
                    " substeps per frame (fastest speed / (time.cfl × domain.cell × time.fps))",
                roundedNumber(substeps(t.cfl, t.fps), 3) + " substeps: up to " + roundedNumber(source + fall, 4) +
                    " m/s (" + roundedNumber(source, 4) + " from emitters and liquid velocity, " +
                    roundedNumber(fall, 4) + " from gravity over the domain) / (" + roundedNumber(t.cfl, 6) + " × " +
                    roundedNumber(h, 6) + " m × " + roundedNumber(t.fps, 6) + " fps)");
  }

  // ---- listeners, solver ----------------------------------------------------------------------

  /// A listener's "head": facing (required) and up (default: against gravity, else +y).
  sim::HeadOrientation headOrientation(const json& object, const std::string& path,
                                       const Vec3& gravity) const {
    check_.rejectUnknownKeys(object, path, {"facing", "up"});
    sim::HeadOrientation head;
    head.facing = check_.requiredVector(object, path, "facing", "direction the nose points");
    if (!(head.facing != Vec3{0.0, 0.0, 0.0}))
      check_.fail(memberPath(path, "facing"), "a non-zero direction", "[0, 0, 0]");
    const bool falling = gravity != Vec3{0.0, 0.0, 0.0};
    head.up = falling ? Vec3{-gravity[0], -gravity[1], -gravity[2]} : Vec3{0.0, 1.0, 0.0};
    if (findMember(object, "up") != nullptr)
      head.up = check_.requiredVector(object, path, "up", "direction of the top of the head");
    if (!acoustics::isHeadOrientation(head.facing, head.up)) {
      const bool given = findMember(object, "up") != nullptr;
      check_.fail(memberPath(path, given ? "up" : "facing"),
                  given ? "a non-zero direction not parallel to facing"
                        : "a direction not parallel to up, which defaults to against gravity (give head.up)",
                  given ? describe(object["up"]) : describe(object["facing"]));
    }
    return head;
  }

  /// "audio.hrtf": a SOFA file of head-related impulse responses that libmysofa reads, resolved
  /// against the scene file's folder; read once here so that a bad one stops the run before it starts.
  fs::path hrtfFile(const json& value) const {
    const std::string expected =
        "the path of a SOFA file of head-related impulse responses (relative to the scene file's folder)";
    const fs::path resolved = (folder_ / fs::path(check_.nonEmptyText(value, "audio.hrtf", expected))).lexically_normal();
    try {
      (void)readHrirTable(resolved);
    } catch (const InputError& error) {
      check_.fail("audio.hrtf", expected, describe(value) + " (" + error.what() + ")");
    }
    return resolved;
  }

  /// Heads without "audio.hrtf" hear through the default set, which must then be installed.
  void requireDefaultHrtf(const sim::Scene& scene) const {
    if (scene.hrtf) return;
    for (std::size_t i = 0; i < scene.listeners.size(); ++i) {
      if (!scene.listeners[i].head) continue;
      try {
        (void)readHrirTable(defaultHrirFile());
      } catch (const InputError& error) {
        check_.fail(memberPath(elementPath("listeners", i), "head"),
                    "a head with an HRTF set: give audio.hrtf, or install Debian's libmysofa1 (MIT KEMAR)",
                    error.what());
      }
      return;
    }
  }

  std::vector<sim::Listener> listeners(const json& root, const sim::Domain& domain,
                                       const Vec3& gravity) const {
    const std::string expected = "an array of 1 or more listeners {name, position}";
    const json* items = check_.optionalArray(root, "", "listeners", expected);
    if (items == nullptr) {  // DESIGN.md: one listener 0.5 m above the domain centre
      sim::Listener listener{"listener", {}, std::nullopt};
      for (std::size_t a = 0; a < 3; ++a)
        listener.position[a] = 0.5 * (domain.min[a] + domain.max[a]);
      listener.position[1] += kDefaultListenerHeight;
      return {listener};
    }
    if (items->empty())
      check_.fail("listeners", expected + " (omit it for the default)", "an empty array");
    // One output channel each: the synthesizer renders at most kMaxListeners (bubble_track.h),
    // so more must fail here, before the simulation, not in synth after it.
    if (items->size() > static_cast<std::size_t>(acoustics::kMaxListeners))
      check_.fail("listeners", "at most " + std::to_string(acoustics::kMaxListeners) + " listeners (one channel each)",
                  std::to_string(items->size()) + " listeners");
    std::vector<sim::Listener> out;
    for (std::size_t i = 0; i < items->size(); ++i) {
      const json& item = (*items)[i];
      const std::string path = elementPath("listeners", i);
      check_.requireObject(item, path, "an object with name and position");
      check_.rejectUnknownKeys(item, path, {"name", "position", "head"});
      sim::Listener listener;
      const std::string namePath = memberPath(path, "name");
      const std::string nameExpected = "a non-empty string (the channel's name)";
      const json* name = findMember(item, "name");
      if (name == nullptr) check_.fail(namePath, nameExpected, std::string(kMissing));
      listener.name = check_.nonEmptyText(*name, namePath, nameExpected);
      for (std::size_t k = 0; k < out.size(); ++k) {
        if (out[k].name == listener.name) {
          check_.fail(namePath,
                      "a name not used by another listener (" + elementPath("listeners", k) +
                          ".name is the same)",
                      describe(*name));
        }
      }
      listener.position = check_.requiredVector(item, path, "position", "metres");
      if (const json* head = check_.optionalObject(item, path, "head", "an object with facing and up"))
        listener.head = headOrientation(*head, memberPath(path, "head"), gravity);
      out.push_back(std::move(listener));
    }
    return out;
  }

  sim::SolverSettings solverSettings(const json& object) const {
    const std::string path = "solver";
    check_.rejectUnknownKeys(object, path,
                             {"transfer", "surface", "flip_ratio", "particles_per_cell", "pressure_tolerance",
                              "max_pressure_iterations"});
    sim::SolverSettings s;
    if (const json* surface = findMember(object, "surface")) {
      const std::string expected = R"("particles" or "level_set")";
      if (surface->is_string() && surface->get_ref<const std::string&>() == "particles") {
        s.surface = sim::SurfaceMethod::Particles;
      } else if (surface->is_string() && surface->get_ref<const std::string&>() == "level_set") {
        s.surface = sim::SurfaceMethod::LevelSet;
      } else {
        check_.fail(memberPath(path, "surface"), expected, describe(*surface));
      }
    }
    if (const json* transfer = findMember(object, "transfer")) {
      const std::string transferPath = memberPath(path, "transfer");
      std::string expected = R"("apic" or "flip")";
      if (transfer->is_string()) {
        const std::string& text = transfer->get_ref<const std::string&>();
        if (text == "apic") {
          s.transfer = sim::TransferScheme::Apic;
        } else if (text == "flip") {
          s.transfer = sim::TransferScheme::Flip;
        } else {
          const std::string suggestion =
              closestKey(text, {"apic", "flip"}, kSceneKeyRules.matchSharedStart);
          if (normalizedKey(text) == "pic") {  // not a typo of "apic": PIC is FLIP at ratio 0
            expected += R"( (PIC is "flip" with flip_ratio 0))";
          } else if (!suggestion.empty()) {
            expected += " (did you mean " + quotedText(suggestion) + "?)";
          }
          check_.fail(transferPath, expected, describe(*transfer));
        }
      } else {
        check_.fail(transferPath, expected, describe(*transfer));
      }
    }
    s.flipRatio = check_.optionalNumber(object, path, "flip_ratio", s.flipRatio,
                                        "a number from 0 to 1 (FLIP share of the FLIP/PIC blend)",
                                        [](double v) { return v >= 0 && v <= 1; });
    if (const json* perCell = findMember(object, "particles_per_cell")) {
      s.particlesPerCell =
          static_cast<int>(check_.wholeNumber(*perCell, memberPath(path, "particles_per_cell"),
                                              "an integer from 1 to 64", 1, kMaxParticlesPerCell));
    }
    s.pressureTolerance =
        check_.optionalNumber(object, path, "pressure_tolerance", s.pressureTolerance,
                              "a number > 0 and <= 0.01 (relative residual)",
                              [](double v) { return v > 0 && v <= kMaxPressureTolerance; });
    if (const json* iterations = findMember(object, "max_pressure_iterations")) {
      s.maxPressureIterations = static_cast<int>(
          check_.wholeNumber(*iterations, memberPath(path, "max_pressure_iterations"),
                             "an integer from 1 to 2147483647", 1,
                             static_cast<std::uint64_t>(std::numeric_limits<int>::max())));
    }
    return s;
  }

  JsonValidator check_;
  fs::path folder_;
};

}  // namespace

sim::Scene parseScene(std::string_view text, const std::filesystem::path& file) {
  const std::string name = file.string();
  const json root = parseJson(text, name, DuplicateKeys::Rejected);
  sim::Scene scene = SceneReader(name, file.parent_path()).read(root);
  scene.file = file;
  return scene;
}

sim::Scene readScene(const std::filesystem::path& path) {
  return parseScene(readInputFile(path), path);
}

sim::Scene withCellSize(sim::Scene scene, double cell, const std::string& source) {
  scene.domain.cell = cell;
  // Shortest round trip ("0.0" -> "0", as typed); JSON has no NaN or infinity (it would say
  // "null"), so those as printf writes them.
  std::string text = std::isfinite(cell) ? formatNumber(cell) : roundedNumber(cell, 6);
  if (text.ends_with(".0")) text.resize(text.size() - 2);
  requireValidCellSize(scene.domain, text,
                       [&](const std::string& expected, const std::string& found) {
                         throw InputError("", source, expected, found);
                       });
  return scene;
}

}  // namespace fluidsound::io
