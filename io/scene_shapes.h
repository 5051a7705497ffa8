// io/scene_shapes.h — scene input: reads the liquid regions, emitters and solids of a
// `fluidsound.scene/1` document (docs/scene.md) into sim records; used by io/scene_file.cpp.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "io/json_validation.h"
#include "sim/scene.h"

namespace fluidsound::io {

/// @brief Requires max > min on every axis of the box object `box` at `path` (keys "min" and
///        "max", already read into `min` and `max` [m]).
/// @throws InputError naming `path.max[a]` of the first axis that is not ordered
void requireOrdered(const JsonValidator& check, const nlohmann::json& box, const std::string& path,
                    const Vec3& min, const Vec3& max);

/// @brief One item of `liquid`: exactly one shape (box, sphere or mesh) and an optional initial
///        velocity [m/s].
/// @param path    the item's JSON path (`liquid[0]`)
/// @param folder  the scene file's folder; a mesh path is stored resolved against it and must
///                name a readable file
/// @throws InputError at the first problem
sim::LiquidRegion readLiquidRegion(const JsonValidator& check, const nlohmann::json& item,
                                   const std::string& path, const std::filesystem::path& folder);

/// @brief One item of `emitters`: a disk (center [m], normal, returned as a unit vector, radius
///        [m]), a speed [m/s], a start [s] (default 0) and an end [s] (default time.duration).
/// @param path  the item's JSON path (`emitters[0]`)
/// @param time  the scene's time settings, for the default end
/// @param domain  the scene's domain: the disk's radius is at most its diagonal and the disk
///                meets it (docs/scene.md, emitters)
/// @throws InputError at the first problem
sim::Emitter readEmitter(const JsonValidator& check, const nlohmann::json& item,
                         const std::string& path, const sim::TimeSettings& time,
                         const sim::Domain& domain);

/// @brief A solid's or body's placement keys: `scale` (> 0, default 1), `translate` [m],
///        `rotate` [degrees about x, y, z] (zero if absent).
void readPlacement(const JsonValidator& check, const nlohmann::json& item, const std::string& path, double& scale,
                   Vec3& translate, Vec3& rotateDegrees);

/// @brief The one shape of a liquid, solid or body item: exactly one of "box", "sphere", "mesh"
///        (a mesh path resolved against `folder`; the file is opened, not read).
sim::Shape readShape(const JsonValidator& check, const nlohmann::json& item, const std::string& path,
                     const std::filesystem::path& folder);

/// @brief One item of `solids`: exactly one shape, a scale factor (default 1), a translation
///        [m], a rotation [degrees about x, y, z] and a path of keys {t [s], translate [m]} in
///        time order.
/// @param path    the item's JSON path (`solids[0]`)
/// @param folder  as for readLiquidRegion
/// @throws InputError at the first problem
sim::Solid readSolid(const JsonValidator& check, const nlohmann::json& item,
                     const std::string& path, const std::filesystem::path& folder);

}  // namespace fluidsound::io
