// sim/core/solid_material.h — what a solid body is made of, as every stage reads it: its density
// for the dynamics, its elasticity and damping for its modes (the named table and the checks are
// acoustics/modal/solid_material.h). Rayleigh damping C = a_M·M + b_K·K.
#pragma once

namespace fluidsound {

/// An isotropic, linearly elastic solid with Rayleigh damping.
struct SolidMaterial {
  double density = 0.0;            ///< ρ [kg/m³], > 0
  double youngsModulus = 0.0;      ///< E [Pa], > 0
  double poissonsRatio = 0.0;      ///< ν [-], in (−1, 0.5)
  double rayleighMass = 0.0;       ///< a_M [1/s], ≥ 0: the mass-proportional damping coefficient
  double rayleighStiffness = 0.0;  ///< b_K [s], ≥ 0: the stiffness-proportional damping coefficient
  bool operator==(const SolidMaterial&) const = default;
};

}  // namespace fluidsound
