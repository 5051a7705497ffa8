// acoustics/modal/solid_material.cpp — the named material table and the material's derived speeds.
#include "acoustics/modal/solid_material.h"

#include <array>
#include <cmath>

namespace fluidsound::acoustics {
namespace {

// ρ, E, ν and the Rayleigh pair (a_M, b_K) of NeuralSound's material table (Jin et al. 2022,
// src/classic/tools.py; shared solids.md §2) for steel, glass, ceramic, wood and plastic. Stone
// (granite) is not in it: ρ, E, ν are handbook values for granite (ρ 2 600–2 700 kg/m³, E 40–70 GPa,
// ν 0.2–0.3), and its damping is chosen to give a loss factor of about 0.01 at 1 kHz, between
// ceramic's and wood's (documented as a choice in docs/solids.md).
constexpr std::array kMaterials{
    NamedSolidMaterial{"steel", {7850.0, 2.0e11, 0.29, 5.0, 3e-8}},
    NamedSolidMaterial{"glass", {2600.0, 6.2e10, 0.20, 1.0, 1e-7}},
    NamedSolidMaterial{"ceramic", {2700.0, 7.2e10, 0.19, 6.0, 1e-7}},
    NamedSolidMaterial{"wood", {750.0, 1.1e10, 0.25, 60.0, 2e-6}},
    NamedSolidMaterial{"stone", {2650.0, 5.0e10, 0.25, 20.0, 1e-6}},
    NamedSolidMaterial{"plastic", {1070.0, 1.4e9, 0.35, 30.0, 1e-6}},
};

}  // namespace

std::span<const NamedSolidMaterial> solidMaterials() { return kMaterials; }

std::optional<SolidMaterial> findSolidMaterial(std::string_view name) {
  for (const NamedSolidMaterial& named : kMaterials)
    if (named.name == name) return named.material;
  return std::nullopt;
}

std::optional<std::string_view> solidMaterialProblem(const SolidMaterial& material) {
  if (!(material.density > 0.0) || !std::isfinite(material.density)) return "density must be > 0";
  if (!(material.youngsModulus > 0.0) || !std::isfinite(material.youngsModulus))
    return "youngsModulus must be > 0";
  if (!(material.poissonsRatio > -1.0 && material.poissonsRatio < 0.5))
    return "poissonsRatio must be in (-1, 0.5)";
  if (!(material.rayleighMass >= 0.0) || !std::isfinite(material.rayleighMass))
    return "rayleighMass must be >= 0";
  if (!(material.rayleighStiffness >= 0.0) || !std::isfinite(material.rayleighStiffness))
    return "rayleighStiffness must be >= 0";
  return std::nullopt;
}

double shearModulus(const SolidMaterial& material) {
  return material.youngsModulus / (2.0 * (1.0 + material.poissonsRatio));
}

double shearWaveSpeed(const SolidMaterial& material) {
  return std::sqrt(shearModulus(material) / material.density);
}

double modalDecayRate(const SolidMaterial& material, double angularFrequency) {
  return 0.5 * (material.rayleighMass + material.rayleighStiffness * angularFrequency * angularFrequency);
}

}  // namespace fluidsound::acoustics
