// tools/transfer_report.h — what transfer.report.json says of a transfer stage (docs/cli.md):
// written by `transfer` and by `run`'s transfer stage.
#pragma once

#include <nlohmann/json.hpp>

#include "acoustics/transfer/transfer_stage.h"
#include "tools/run_report.h"
#include "tools/transfer_choice.h"
#include "tools/transfer_command.h"

namespace fluidsound::tools {

/// The settings (scene, output, transfer model and its settings, oscillator model) and results
/// (bubbles, samples, frames read; for the geometric model its solver statistics) of `result`,
/// and its stage time; the command's seconds are added by the caller.
void addTransferResults(RunReport& report, const TransferOptions& options,
                        const TransferChoice& choice, const acoustics::TransferResult& result);

/// @brief What report.json's run.transfer says (docs/cli.md, `run`): the model and its settings
///        and, for the geometric model, its solver statistics, copied from a transfer.report.json
///        document (empty for one that is not an object).
nlohmann::ordered_json transferSummary(const nlohmann::ordered_json& transferReport);

}  // namespace fluidsound::tools
