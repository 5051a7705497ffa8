// acoustics/modal/solid_material.h — the named table of materials a scene's `material` picks from,
// the checks of a material and what follows from it (docs/solids.md, Materials; the record itself
// is sim/core/solid_material.h).
// Rayleigh damping in one convention throughout: C = a_M·M + b_K·K, so a mode of undamped angular
// frequency ω decays at d = (a_M + b_K·ω²)/2 [1/s] (shared solids.md §1.1 and T6).
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "sim/core/solid_material.h"

namespace fluidsound::acoustics {

/// A material of the table, by name.
struct NamedSolidMaterial {
  std::string_view name;
  SolidMaterial material;
};

/// The named materials: steel, glass, ceramic, wood, stone, plastic (values and their sources in
/// docs/solids.md, Materials).
std::span<const NamedSolidMaterial> solidMaterials();

/// The named material, or nothing for an unknown name.
std::optional<SolidMaterial> findSolidMaterial(std::string_view name);

/// Why the material cannot be used ("youngsModulus must be > 0"), naming the field; nothing when
/// it can.
std::optional<std::string_view> solidMaterialProblem(const SolidMaterial& material);

/// Shear modulus μ = E / (2(1 + ν)) [Pa].
double shearModulus(const SolidMaterial& material);

/// Shear-wave speed c_s = √(μ/ρ) [m/s].
double shearWaveSpeed(const SolidMaterial& material);

/// Decay rate of a mode of undamped angular frequency ω [rad/s]: d = (a_M + b_K·ω²)/2 [1/s].
double modalDecayRate(const SolidMaterial& material, double angularFrequency);

}  // namespace fluidsound::acoustics
