// io/scene_bubbles.h — scene input: the optional `bubbles` block of a `fluidsound.scene/1`
// document (docs/bubbles.md, docs/scene.md) into sim::BubbleSettings; used by io/scene_file.cpp.
#pragma once

#include <nlohmann/json.hpp>

#include "io/json_validation.h"
#include "sim/bubbles/bubble_settings.h"

namespace fluidsound::io {

/// @brief The `bubbles` object: every member optional (absent: the default of BubbleSettings),
///        unknown keys rejected; `sizes` is {"power_law": {min_radius, max_radius, hinze_radius}}
///        or {"gaussian": {mean_radius, radius_deviation, min_radius, max_radius}}.
/// @throws InputError naming the JSON path (`bubbles.rate`, `bubbles.sizes.power_law.max_radius`)
sim::BubbleSettings readBubbleSettings(const JsonValidator& check, const nlohmann::json& object);

}  // namespace fluidsound::io
