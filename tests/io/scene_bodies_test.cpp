// tests/io/scene_bodies_test.cpp — the scene's `bodies` (docs/scene.md, "bodies"; issue 22's bad
// input: an unknown material, non-positive moduli, Poisson's ratio outside (−1, 0.5), an open body
// mesh): each mistake one line naming the file, the JSON path and what was expected.
#include "io/scene_bodies.h"

#include <gtest/gtest.h>

#include <string>

#include "io/scene_documents.h"
#include "io/scene_file.h"
#include "io/scene_meshes.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

using namespace scene_test;

json withBodies(const char* bodies) { return withChange(minimalScene(), "/bodies", bodies); }

TEST(SceneBodies, ReadsABodyWithTheTablesMaterialAndDefaults) {
  const sim::Scene scene = parseScene(withBodies(R"([
    { "sphere": { "center": [0.1, 0.15, 0.05], "radius": 0.01 }, "material": "steel", "velocity": [0, -1, 0] },
    { "name": "table", "box": { "min": [0, 0, 0], "max": [0.2, 0.02, 0.1] }, "static": true,
      "material": { "density": 700, "youngs_modulus": 1e10, "poissons_ratio": 0.3, "rayleigh_mass": 50 },
      "friction": 0.4, "restitution": 0.6, "resolution": 40 } ])").dump(), "tank.json");
  ASSERT_EQ(scene.bodies.size(), 2u);
  const sim::SceneBody& ball = scene.bodies[0];
  EXPECT_EQ(ball.name, "body 0");
  EXPECT_EQ(ball.materialName, "steel");
  EXPECT_EQ(ball.material.youngsModulus, 2e11);
  EXPECT_FALSE(ball.isStatic);
  EXPECT_EQ(ball.velocity, (Vec3{0, -1, 0}));
  EXPECT_EQ(ball.friction, 0.5);
  EXPECT_EQ(ball.restitution, 0.3);
  EXPECT_EQ(ball.resolution, 32);
  const sim::SceneBody& table = scene.bodies[1];
  EXPECT_EQ(table.name, "table");
  EXPECT_TRUE(table.isStatic);
  EXPECT_EQ(table.materialName, "");
  EXPECT_EQ(table.material.density, 700.0);
  EXPECT_EQ(table.material.rayleighMass, 50.0);
  EXPECT_EQ(table.material.rayleighStiffness, 0.0);
  EXPECT_EQ(table.resolution, 40);
}

struct BodyCase {
  const char* name;
  const char* body;       ///< the one item of `bodies`
  std::string field;      ///< the JSON path the error names
  std::string expected;   ///< part of what it says was expected
};

class SceneBodyErrors : public ::testing::TestWithParam<BodyCase> {};

TEST_P(SceneBodyErrors, NameTheFieldAndWhatWasExpected) {
  const BodyCase& c = GetParam();
  const std::string bodies = std::string("[") + c.body + "]";
  expectError(parseError(withBodies(bodies.c_str()).dump()), c.field, c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    Bodies, SceneBodyErrors,
    ::testing::Values(
        BodyCase{"unknown_material", R"({ "sphere": { "center": [0, 0.1, 0], "radius": 0.01 }, "material": "steal" })",
                 "bodies[0].material", R"(one of "steel", "glass", "ceramic", "wood", "stone", "plastic", or an object of its constants (did you mean "steel"?))"},
        BodyCase{"missing_material", R"({ "sphere": { "center": [0, 0.1, 0], "radius": 0.01 } })", "bodies[0].material",
                 "a material name"},
        BodyCase{"zero_youngs_modulus",
                 R"({ "sphere": { "center": [0, 0.1, 0], "radius": 0.01 }, "material": { "density": 1000, "youngs_modulus": 0, "poissons_ratio": 0.3 } })",
                 "bodies[0].material.youngs_modulus", "a Young's modulus > 0 (Pa)"},
        BodyCase{"negative_density",
                 R"({ "sphere": { "center": [0, 0.1, 0], "radius": 0.01 }, "material": { "density": -1, "youngs_modulus": 1e9, "poissons_ratio": 0.3 } })",
                 "bodies[0].material.density", "a density > 0"},
        BodyCase{"poissons_ratio_half",
                 R"({ "sphere": { "center": [0, 0.1, 0], "radius": 0.01 }, "material": { "density": 1000, "youngs_modulus": 1e9, "poissons_ratio": 0.5 } })",
                 "bodies[0].material.poissons_ratio", "a Poisson's ratio in (-1, 0.5)"},
        BodyCase{"poissons_ratio_minus_one",
                 R"({ "sphere": { "center": [0, 0.1, 0], "radius": 0.01 }, "material": { "density": 1000, "youngs_modulus": 1e9, "poissons_ratio": -1 } })",
                 "bodies[0].material.poissons_ratio", "a Poisson's ratio in (-1, 0.5)"},
        BodyCase{"static_not_bool", R"({ "sphere": { "center": [0, 0.1, 0], "radius": 0.01 }, "material": "wood", "static": 1 })",
                 "bodies[0].static", "true or false"},
        BodyCase{"restitution_above_one", R"({ "sphere": { "center": [0, 0.1, 0], "radius": 0.01 }, "material": "wood", "restitution": 1.5 })",
                 "bodies[0].restitution", "a restitution in [0, 1]"},
        BodyCase{"resolution_one", R"({ "sphere": { "center": [0, 0.1, 0], "radius": 0.01 }, "material": "wood", "resolution": 1 })",
                 "bodies[0].resolution", "an integer from 2 to 400"},
        BodyCase{"no_shape", R"({ "material": "wood" })", "bodies[0]", "exactly one shape: box, sphere or mesh"}),
    [](const ::testing::TestParamInfo<BodyCase>& info) { return std::string(info.param.name); });

// An open mesh (a box missing one triangle) as a body: loading the scene's meshes names the file
// and `bodies[0].mesh`.
TEST(SceneBodies, OpenBodyMeshIsRefusedNamingItsJsonPath) {
  test::TempFolder folder;
  writeFile(folder.path() / "open.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
            "f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\nf 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\n");
  writeFile(folder.path() / "scene.json",
            withBodies(R"([{ "mesh": "open.obj", "material": "ceramic", "static": true }])").dump());
  sim::Scene scene = readScene(folder.path() / "scene.json");
  try {
    loadSceneMeshes(scene);
    FAIL() << "an open body mesh was accepted";
  } catch (const InputError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("open.obj"), std::string::npos) << text;
    EXPECT_NE(text.find("bodies[0].mesh"), std::string::npos) << text;
    EXPECT_NE(text.find("closed"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace fluidsound::io

namespace fluidsound::io {
namespace {

using namespace scene_test;

json withSamples(const char* samples) { return withChange(minimalScene(), "/collision_samples", samples); }

// `collision_samples` (docs/scene.md): a pair of the table's material names (or "domain"), files
// resolved against the scene's folder, peak_pa; each mistake names its JSON path.
TEST(SceneCollisionSamples, ReadsAPairAndNamesEachMistake) {
  const sim::Scene scene = parseScene(
      withSamples(R"([ { "materials": ["stone", "domain"], "impact": "hits/stone.wav", "peak_pa": 3 } ])").dump(),
      "scenes/tank.json");
  ASSERT_EQ(scene.collisionSamples.size(), 1u);
  EXPECT_EQ(scene.collisionSamples[0].materials[1], "domain");
  EXPECT_EQ(scene.collisionSamples[0].impact, std::filesystem::path("scenes/hits/stone.wav"));
  EXPECT_TRUE(scene.collisionSamples[0].slide.empty());
  EXPECT_EQ(scene.collisionSamples[0].peakPascals, 3.0);
  expectError(parseError(withSamples(R"([ { "materials": ["stone", "granite"], "impact": "a.wav" } ])").dump()),
              "collision_samples[0].materials[1]", "two material names");
  expectError(parseError(withSamples(R"([ { "materials": ["stone"], "impact": "a.wav" } ])").dump()),
              "collision_samples[0].materials", "two material names");
  expectError(parseError(withSamples(R"([ { "materials": ["stone", "wood"] } ])").dump()), "collision_samples[0]",
              "at least one of impact, slide, roll");
  expectError(parseError(withSamples(R"([ { "materials": ["stone", "wood"], "roll": "r.wav", "peak_pa": 0 } ])").dump()),
              "collision_samples[0].peak_pa", "a pressure > 0");
  expectError(parseError(withSamples(R"([ { "materials": ["stone", "wood"], "hit": "r.wav" } ])").dump()),
              "collision_samples[0].hit", "one of");
}

}  // namespace
}  // namespace fluidsound::io
