// tests/tools/modes_command_test.cpp — `fluidsound modes` (issue 22; docs/solids.md) against the
// analytic modes of shared solids.md §4: a free–free steel bar (T1), the same bar as a cantilever
// (T2), a free square plate (T3, Leissa 1969) and a free steel sphere (T4, Lamb 1882), each
// through the real executable from a mesh file, as a user checks a model; and its bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "acoustics/modal/solid_material.h"
#include "support/command_runner.h"
#include "support/temp_folder.h"
#include "support/test_meshes.h"

namespace fluidsound {
namespace {

namespace fs = std::filesystem;
using test::runFluidsound;
using test::shellQuoted;

constexpr int kExitUsage = 2, kExitBadInput = 3;  // docs/cli.md

void writeObj(const fs::path& path, const sim::TriangleMesh& mesh, double scale = 1.0) {
  std::ofstream out(path);
  out.precision(9);
  for (const auto& v : mesh.vertices) out << "v " << scale * v[0] << ' ' << scale * v[1] << ' ' << scale * v[2] << '\n';
  for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

/// `fluidsound modes ARGS --json -q`, its standard output parsed.
nlohmann::json modesJson(const fs::path& folder, const std::string& arguments) {
  const fs::path out = folder / "modes.json";
  const std::string command = shellQuoted(FLUIDSOUND_EXECUTABLE) + " modes " + arguments + " --json -q > " +
                              shellQuoted(out.string());
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(out);
  return nlohmann::json::parse(in);
}

/// The frequencies [Hz] of the modes whose surface moves mostly (> 90 %) along `axis`, ascending.
std::vector<double> modesMovingAlong(const nlohmann::json& result, int axis) {
  std::vector<double> f;
  for (const auto& mode : result["modes"])
    if (mode["surface_motion_xyz"][axis].get<double>() > 0.9) f.push_back(mode["frequency_hz"].get<double>());
  return f;
}

constexpr double kBarLength = 0.5, kBarWidth = 0.02, kBarThickness = 0.01;  // [m], thickness along z

/// Euler–Bernoulli bending across the thickness, free–free: f_n = (β_nL)²/(2πL²)·(h/√12)·√(E/ρ)
/// with β_nL = 4.7300, 7.8532, 10.9956 (shared solids.md T1: 207.5, 572.1, 1121.5 Hz).
constexpr double kFreeFreeRoots[] = {4.7300, 7.8532, 10.9956};

double eulerBernoulli(double root) {
  const auto steel = *acoustics::findSolidMaterial("steel");
  return root * root / (2.0 * std::numbers::pi * kBarLength * kBarLength) * kBarThickness / std::sqrt(12.0) *
         std::sqrt(steel.youngsModulus / steel.density);
}

/// The same with Timoshenko's first-order correction for shear and rotary inertia,
/// f ≈ f_EB·(1 − ½(β_n r)²(1 + E/(κG))), r = h/√12, κ = 5/6 (Timoshenko 1921; exact to that
/// order for a simply supported beam, and the leading term for the free one): the 3-D answer the
/// voxels converge to lies 0.15 %, 0.42 % and 0.83 % below Euler–Bernoulli for the three modes.
double timoshenko(double root) {
  const auto steel = *acoustics::findSolidMaterial("steel");
  const double beta = root / kBarLength, r = kBarThickness / std::sqrt(12.0);
  const double shear = 2.0 * (1.0 + steel.poissonsRatio) / (5.0 / 6.0);  // E/(κG)
  return eulerBernoulli(root) * (1.0 - 0.5 * beta * beta * r * r * (1.0 + shear));
}

class ModesCommand : public ::testing::Test {
 protected:
  test::TempFolder folder;
  fs::path bar() {
    const fs::path path = folder.path() / "bar.obj";
    writeObj(path, test::boxMesh({0, 0, 0}, {float(kBarLength), float(kBarWidth), float(kBarThickness)}));
    return path;
  }
};

// T1: the free–free bar's first three bending modes across its thickness within 3 % of
// Euler–Bernoulli (the tolerance) at 5 mm and 2.5 mm voxels, and their error against the
// 3-D (Timoshenko) answer falling as the voxels shrink; six rigid modes dropped.
TEST_F(ModesCommand, FreeFreeSteelBarBendsAtItsAnalyticFrequencies) {
  const fs::path mesh = bar();
  std::vector<double> previousError(3, 1.0);
  for (int resolution : {100, 200}) {
    const nlohmann::json result = modesJson(folder.path(), shellQuoted(mesh.string()) + " --material steel --modes 12 "
                                                           "--resolution " + std::to_string(resolution));
    EXPECT_EQ(result["rigid_modes_dropped"], 6);
    const std::vector<double> bending = modesMovingAlong(result, 2);
    ASSERT_GE(bending.size(), 3u) << resolution;
    for (int n = 0; n < 3; ++n) {
      const double f = bending[n], reference = eulerBernoulli(kFreeFreeRoots[n]);
      EXPECT_NEAR(f, reference, 0.03 * reference) << "mode " << n + 1 << ", resolution " << resolution;
      const double error = std::abs(f / timoshenko(kFreeFreeRoots[n]) - 1.0);
      EXPECT_LT(error, previousError[n]) << "mode " << n + 1 << ", resolution " << resolution;
      previousError[n] = error;
    }
  }
}

// T2: clamped at x = 0, the bar's bending modes stand in the ratios of β_nL = 1.8751, 4.6941,
// 7.8548 squared, 1 : 6.267 : 17.55, within 3 % (the tolerance).
TEST_F(ModesCommand, CantileverBarKeepsItsRatios) {
  const nlohmann::json result =
      modesJson(folder.path(), shellQuoted(bar().string()) + " --material steel --modes 10 --resolution 200 --clamp -x");
  EXPECT_EQ(result["rigid_modes_dropped"], 0);
  const std::vector<double> bending = modesMovingAlong(result, 2);
  ASSERT_GE(bending.size(), 3u);
  EXPECT_NEAR(bending[1] / bending[0], 6.267, 0.03 * 6.267);
  EXPECT_NEAR(bending[2] / bending[0], 17.55, 0.03 * 17.55);
}

// T3: a free square plate, a = 0.1 m, h = 2 mm (h/a = 0.02), ν = 0.3: Leissa's λ = ωa²√(ρh/D) =
// 13.47, 19.60, 24.27, 34.80 (the last twice), so the ratios to the first within 4 % (the issue's
// tolerance), and the pair degenerate within 0.1 % (the square's symmetry, which the voxel grid
// keeps). One voxel through the thickness: the elements' incompatible modes carry the bending.
TEST_F(ModesCommand, FreeSquarePlateFollowsLeissa) {
  const fs::path mesh = folder.path() / "plate.obj";
  writeObj(mesh, test::boxMesh({0, 0, 0}, {0.1f, 0.1f, 0.002f}));
  const nlohmann::json result = modesJson(
      folder.path(), shellQuoted(mesh.string()) + " --material steel --poissons-ratio 0.3 --modes 5 --resolution 50");
  std::vector<double> f;
  for (const auto& mode : result["modes"]) f.push_back(mode["frequency_hz"].get<double>());
  ASSERT_GE(f.size(), 5u);
  const double leissa[] = {13.47, 19.60, 24.27, 34.80, 34.80};
  for (int n = 1; n < 5; ++n) EXPECT_NEAR(f[n] / f[0], leissa[n] / leissa[0], 0.04 * leissa[n] / leissa[0]) << n;
  EXPECT_NEAR(f[4] / f[3], 1.0, 1e-3);
}

// T4: a free steel sphere of radius a = 0.1 m: its lowest mode, the ℓ = 2 torsional one, at
// ωa/c_s = 2.5011 within 3 % (the tolerance) and five-fold degenerate: the five within
// 0.5 % of each other (shared solids.md T4's tolerance; the cubic voxels split them into three and
// two). 12 voxels per radius; the icosphere's 5 120 triangles lie within 0.05 % of the sphere.
TEST_F(ModesCommand, FreeSteelSphereRingsAtLambsFrequencyFiveTimesOver) {
  const fs::path mesh = folder.path() / "sphere.obj";
  const double radius = 0.1;
  writeObj(mesh, test::icosphere(4), radius);
  const nlohmann::json result =
      modesJson(folder.path(), shellQuoted(mesh.string()) + " --material steel --modes 6 --resolution 24");
  ASSERT_GE(result["modes"].size(), 5u);
  const double cs = acoustics::shearWaveSpeed(*acoustics::findSolidMaterial("steel"));
  std::vector<double> x;
  for (int n = 0; n < 5; ++n) x.push_back(2.0 * std::numbers::pi * result["modes"][n]["frequency_hz"].get<double>() * radius / cs);
  for (double value : x) EXPECT_NEAR(value, 2.5011, 0.03 * 2.5011);
  EXPECT_LT(x[4] / x[0] - 1.0, 0.005);
}

// --cache: the first run writes KEY.modes, the second reads it and prints the same modes; another
// material is another key.
TEST_F(ModesCommand, CacheGivesTheSameModesAgain) {
  const std::string args = shellQuoted(bar().string()) + " --modes 6 --resolution 50 --cache " +
                           shellQuoted((folder.path() / "cache").string());
  const nlohmann::json first = modesJson(folder.path(), args), second = modesJson(folder.path(), args);
  EXPECT_EQ(first["cache"], "written");
  EXPECT_EQ(second["cache"], "read");
  EXPECT_EQ(first["modes"], second["modes"]);
  EXPECT_EQ(first["cache_file"], second["cache_file"]);
  const nlohmann::json glass = modesJson(folder.path(), args + " --material glass");
  EXPECT_EQ(glass["cache"], "written");
  EXPECT_NE(glass["cache_file"], first["cache_file"]);
}

TEST_F(ModesCommand, BadInputExitsNamingWhatIsWrong) {
  const std::string mesh = bar().string();
  auto outcome = runFluidsound({"modes", mesh, "--material", "unobtainium"});
  EXPECT_EQ(outcome.exitCode, kExitUsage);
  EXPECT_NE(outcome.err.find("--material"), std::string::npos) << outcome.err;
  for (const char* option : {"--youngs-modulus", "--density"}) {
    outcome = runFluidsound({"modes", mesh, option, "0"});
    EXPECT_EQ(outcome.exitCode, kExitUsage) << option;
    EXPECT_NE(outcome.err.find(option), std::string::npos) << outcome.err;
  }
  for (const char* nu : {"0.5", "-1", "nan"}) {
    outcome = runFluidsound({"modes", mesh, "--poissons-ratio", nu});
    EXPECT_EQ(outcome.exitCode, kExitUsage) << nu;
    EXPECT_NE(outcome.err.find("--poissons-ratio"), std::string::npos) << outcome.err;
  }
  // An open mesh: the box without its last triangle.
  sim::TriangleMesh open = test::boxMesh({0, 0, 0}, {0.1f, 0.1f, 0.1f});
  open.triangles.pop_back();
  const fs::path openPath = folder.path() / "open.obj";
  writeObj(openPath, open);
  outcome = runFluidsound({"modes", openPath.string()});
  EXPECT_EQ(outcome.exitCode, kExitBadInput);
  EXPECT_NE(outcome.err.find("open.obj"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("closed"), std::string::npos) << outcome.err;
  outcome = runFluidsound({"modes", (folder.path() / "missing.obj").string()});
  EXPECT_EQ(outcome.exitCode, kExitBadInput);
  EXPECT_NE(outcome.err.find("missing.obj"), std::string::npos) << outcome.err;
  // Voxels coarser than the bar is thick: none inside.
  outcome = runFluidsound({"modes", mesh, "--resolution", "20"});
  EXPECT_EQ(outcome.exitCode, kExitBadInput);
  EXPECT_NE(outcome.err.find("--resolution"), std::string::npos) << outcome.err;
  EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
}

}  // namespace
}  // namespace fluidsound
