// io/scene_bodies.cpp — see scene_bodies.h.
#include "io/scene_bodies.h"

#include <string_view>
#include <vector>

#include "acoustics/modal/solid_material.h"
#include "io/scene_shapes.h"

namespace fluidsound::io {
namespace {

using json = nlohmann::json;

/// Voxels along a body's longest side: at least 2, at most what a modal analysis of a solid
/// block finishes in minutes (400³ voxels would be 2·10⁸ unknowns).
constexpr std::uint64_t kMinResolution = 2, kMaxResolution = 400;

std::string materialNames() {
  std::string names;
  for (const acoustics::NamedSolidMaterial& m : acoustics::solidMaterials())
    names += (names.empty() ? "" : ", ") + quotedText(m.name);
  return names;
}

void readMaterial(const JsonValidator& check, const json& value, const std::string& path, sim::SceneBody& body) {
  if (value.is_string()) {
    const std::string& name = value.get_ref<const std::string&>();
    const auto found = acoustics::findSolidMaterial(name);
    if (!found) {
      std::vector<std::string_view> known;
      for (const auto& m : acoustics::solidMaterials()) known.push_back(m.name);
      std::string expected = "one of " + materialNames() + ", or an object of its constants";
      const std::string suggestion = closestKey(name, known, true);
      if (!suggestion.empty()) expected += " (did you mean " + quotedText(suggestion) + "?)";
      check.fail(path, expected, describe(value));
    }
    body.materialName = name;
    body.material = *found;
    return;
  }
  check.requireObject(value, path, "a material name (" + materialNames() + ") or an object of its constants");
  check.rejectUnknownKeys(value, path, {"density", "youngs_modulus", "poissons_ratio", "rayleigh_mass", "rayleigh_stiffness"});
  SolidMaterial& m = body.material;
  m.density = check.requiredNumber(value, path, "density", "a density > 0 (kg/m^3)", positive);
  m.youngsModulus = check.requiredNumber(value, path, "youngs_modulus", "a Young's modulus > 0 (Pa)", positive);
  m.poissonsRatio = check.requiredNumber(value, path, "poissons_ratio", "a Poisson's ratio in (-1, 0.5)",
                                         [](double v) { return v > -1.0 && v < 0.5; });
  m.rayleighMass = check.optionalNumber(value, path, "rayleigh_mass", 0.0, "a number >= 0 (1/s)", nonNegative);
  m.rayleighStiffness = check.optionalNumber(value, path, "rayleigh_stiffness", 0.0, "a number >= 0 (s)", nonNegative);
}

bool boolean(const JsonValidator& check, const json& value, const std::string& path) {
  if (!value.is_boolean()) check.fail(path, "true or false", describe(value));
  return value.get<bool>();
}

}  // namespace

sim::SceneBody readSceneBody(const JsonValidator& check, const json& item, const std::string& path,
                             const std::filesystem::path& folder, std::size_t index) {
  check.requireObject(item, path, "an object with one of box, sphere or mesh, and a material");
  check.rejectUnknownKeys(item, path,
                          {"name", "box", "sphere", "mesh", "scale", "translate", "rotate", "material", "static",
                           "velocity", "angular_velocity", "friction", "restitution", "resolution"});
  sim::SceneBody body;
  body.name = "body " + std::to_string(index);
  if (const json* name = findMember(item, "name")) body.name = check.nonEmptyText(*name, memberPath(path, "name"), "a name");
  body.shape = readShape(check, item, path, folder);
  readPlacement(check, item, path, body.scale, body.translate, body.rotateDegrees);
  const json* material = findMember(item, "material");
  if (material == nullptr)
    check.fail(memberPath(path, "material"), "a material name (" + materialNames() + ") or an object of its constants",
               std::string(kMissing));
  readMaterial(check, *material, memberPath(path, "material"), body);
  if (const json* fixed = findMember(item, "static")) body.isStatic = boolean(check, *fixed, memberPath(path, "static"));
  if (const json* v = findMember(item, "velocity")) body.velocity = check.vector(*v, memberPath(path, "velocity"), "m/s");
  if (const json* w = findMember(item, "angular_velocity"))
    body.angularVelocity = check.vector(*w, memberPath(path, "angular_velocity"), "rad/s");
  body.friction = check.optionalNumber(item, path, "friction", 0.5, "a friction coefficient >= 0", nonNegative);
  body.restitution = check.optionalNumber(item, path, "restitution", 0.3, "a restitution in [0, 1]",
                                          [](double e) { return e >= 0.0 && e <= 1.0; });
  if (const json* resolution = findMember(item, "resolution"))
    body.resolution = static_cast<int>(check.wholeNumber(*resolution, memberPath(path, "resolution"),
                                                         "an integer from 2 to 400 (voxels along the longest side)",
                                                         kMinResolution, kMaxResolution));
  return body;
}

sim::CollisionSamples readCollisionSamples(const JsonValidator& check, const json& item, const std::string& path,
                                           const std::filesystem::path& folder) {
  check.requireObject(item, path, "an object with materials and at least one of impact, slide, roll");
  check.rejectUnknownKeys(item, path, {"materials", "impact", "slide", "roll", "peak_pa"});
  sim::CollisionSamples samples;
  const std::string materialsPath = memberPath(path, "materials");
  const json* materials = findMember(item, "materials");
  const std::string expected = "two material names (" + materialNames() + ", or \"domain\" for the walls)";
  if (!materials || !materials->is_array() || materials->size() != 2)
    check.fail(materialsPath, expected, materials ? describe(*materials) : "nothing");
  for (std::size_t k = 0; k < 2; ++k) {
    const std::string name = check.nonEmptyText((*materials)[k], elementPath(materialsPath, k), expected);
    if (name != "domain" && !acoustics::findSolidMaterial(name))
      check.fail(elementPath(materialsPath, k), expected, quotedText(name));
    samples.materials[k] = name;
  }
  bool any = false;
  for (const auto& [key, file] : {std::pair{"impact", &samples.impact}, std::pair{"slide", &samples.slide},
                                  std::pair{"roll", &samples.roll}}) {
    if (const json* value = findMember(item, key)) {
      *file = (folder / check.nonEmptyText(*value, memberPath(path, key), "the path of a recording (WAV or FLAC)"))
                  .lexically_normal();
      any = true;
    }
  }
  if (!any) check.fail(path, "at least one of impact, slide, roll", "none of them");
  samples.peakPascals = check.optionalNumber(item, path, "peak_pa", 1.0, "a pressure > 0 (Pa)",
                                             [](double v) { return v > 0.0 && v < 1e6; });
  return samples;
}

}  // namespace fluidsound::io
