// io/scene_bodies.h — the scene's `bodies` array (docs/scene.md, "bodies"; docs/solids.md): rigid
// bodies that move and sound, each validated field by field with its JSON path.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "io/json_validation.h"
#include "sim/scene.h"

namespace fluidsound::io {

/// @brief One item of `bodies` at `path` (`bodies[2]`): exactly one of box, sphere or mesh (as a
///        solid's, with scale, rotate, translate), a material (a name of the table, or an object
///        of density, youngs_modulus, poissons_ratio, rayleigh_mass, rayleigh_stiffness),
///        static, velocity, angular_velocity, friction, restitution, resolution.
/// @throws InputError naming the file, the JSON path and what was expected (an unknown material
///         with the known names, a modulus ≤ 0, ν outside (−1, 0.5), …)
sim::SceneBody readSceneBody(const JsonValidator& check, const nlohmann::json& item, const std::string& path,
                             const std::filesystem::path& folder, std::size_t index);

/// @brief One item of `collision_samples` at `path`: `materials` (two of the table's names or
///        "domain"), at least one of `impact`, `slide`, `roll` (file paths relative to `folder`),
///        `peak_pa` (> 0, default 1). The files are read and checked by io::loadCollisionSamples.
/// @throws InputError naming the file, the JSON path and what was expected
sim::CollisionSamples readCollisionSamples(const JsonValidator& check, const nlohmann::json& item,
                                           const std::string& path, const std::filesystem::path& folder);

}  // namespace fluidsound::io
