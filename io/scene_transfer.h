// io/scene_transfer.h — scene input: the optional `transfer` block of a `fluidsound.scene/1`
// document (docs/scene.md, docs/transfer.md) into sim::TransferSettings; used by
// io/scene_file.cpp.
#pragma once

#include <nlohmann/json.hpp>

#include "io/json_validation.h"
#include "sim/scene.h"

namespace fluidsound::io {

/// @brief The `transfer` object {model, max_bands, loss_factor}: every member optional (absent:
///        model "geometric", the numbers the geometric model's defaults), unknown keys rejected;
///        `model` is "geometric" or "image", `max_bands` an integer 2 …
///        acoustics::kMaxTransferBands, `loss_factor` a number > 0 and ≤ 0.1.
/// @throws InputError naming the JSON path (`transfer.model`, `transfer.max_bands`)
sim::TransferSettings readTransferSettings(const JsonValidator& check,
                                           const nlohmann::json& object);

}  // namespace fluidsound::io
