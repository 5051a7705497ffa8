// acoustics/modal/solid_material.h — the elastic and damping constants of a sounding solid, and the
// named table a scene's `material` picks from (docs/solids.md, Materials).
// Rayleigh damping in one convention throughout: C = a_M·M + b_K·K, so a mode of undamped angular
// frequency ω decays at d = (a_M + b_K·ω²)/2 [1/s] (shared solids.md §1.1 and T6).
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace fluidsound::acoustics {

/// An isotropic, linearly elastic solid with Rayleigh damping.
struct SolidMaterial {
  std::string_view name;     ///< the table's name ("steel"), or empty for a scene's own values
  double density;            ///< ρ [kg/m³], > 0
  double youngsModulus;      ///< E [Pa], > 0
  double poissonsRatio;      ///< ν [-], in (−1, 0.5)
  double rayleighMass;       ///< a_M [1/s], ≥ 0: the mass-proportional damping coefficient
  double rayleighStiffness;  ///< b_K [s], ≥ 0: the stiffness-proportional damping coefficient
};

/// The named materials: steel, glass, ceramic, wood, stone, plastic (values and their sources in
/// docs/solids.md, Materials).
std::span<const SolidMaterial> solidMaterials();

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
