// tests/acoustics/modal/solid_material_test.cpp — the material table, its checks, and Rayleigh
// damping's decay rates against shared solids.md T6.
#include "acoustics/modal/solid_material.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace fluidsound::acoustics {
namespace {

TEST(SolidMaterial, TableHoldsTheSixNamedMaterialsAllUsable) {
  for (const char* name : {"steel", "glass", "ceramic", "wood", "stone", "plastic"}) {
    const auto material = findSolidMaterial(name);
    ASSERT_TRUE(material) << name;
    EXPECT_FALSE(solidMaterialProblem(*material)) << name;
  }
  EXPECT_EQ(solidMaterials().size(), 6u);
  EXPECT_FALSE(findSolidMaterial("unobtainium"));
}

TEST(SolidMaterial, ProblemsNameTheField) {
  const SolidMaterial steel = *findSolidMaterial("steel");
  auto broken = steel;
  broken.youngsModulus = 0.0;
  EXPECT_EQ(std::string(*solidMaterialProblem(broken)), "youngsModulus must be > 0");
  broken = steel;
  broken.density = -1.0;
  EXPECT_EQ(std::string(*solidMaterialProblem(broken)), "density must be > 0");
  for (double nu : {-1.0, 0.5, 0.7, std::nan("")}) {
    broken = steel;
    broken.poissonsRatio = nu;
    EXPECT_EQ(std::string(*solidMaterialProblem(broken)), "poissonsRatio must be in (-1, 0.5)") << nu;
  }
  broken = steel;
  broken.rayleighStiffness = -1e-9;
  EXPECT_EQ(std::string(*solidMaterialProblem(broken)), "rayleighStiffness must be >= 0");
}

// Steel's shear-wave speed √(E/(2(1+ν)ρ)) = 3 142 m/s (shared solids.md T4: c_s = 3142 m/s).
TEST(SolidMaterial, SteelShearWaveSpeed) {
  EXPECT_NEAR(shearWaveSpeed(*findSolidMaterial("steel")), 3142.0, 1.0);
}

// T6: Q = ω/(α + βω²) = ω/(2d); steel (α 5, β 3e-8) gives 249 / 1016 / 908 / 347 at
// 200 Hz / 1 kHz / 5 kHz / 15 kHz, wood (60, 2e-6) 20 / 45 / 15 / 5 (printed to the digit).
TEST(SolidMaterial, RayleighDecayGivesTheTabulatedQualityFactors) {
  const auto quality = [](const SolidMaterial& m, double f) {
    const double omega = 2.0 * std::numbers::pi * f;
    return omega / (2.0 * modalDecayRate(m, omega));
  };
  const double frequencies[] = {200.0, 1000.0, 5000.0, 15000.0};
  const double steelQ[] = {249.0, 1016.0, 908.0, 347.0};
  const double woodQ[] = {20.0, 45.0, 15.0, 5.0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(quality(*findSolidMaterial("steel"), frequencies[i]), steelQ[i], 0.5) << frequencies[i];
    EXPECT_NEAR(quality(*findSolidMaterial("wood"), frequencies[i]), woodQ[i], 0.5) << frequencies[i];
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
