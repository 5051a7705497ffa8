// tools/transfer_report.h — what transfer.report.json says of a transfer stage (docs/cli.md):
// written by `transfer` and by `run`'s transfer stage.
#pragma once

#include "acoustics/transfer/transfer_stage.h"
#include "tools/run_report.h"
#include "tools/transfer_command.h"

namespace fluidsound::tools {

/// The settings (scene, output, model, oscillator model) and results (bubbles, samples, frames
/// read) of `result`, and its stage time; the command's seconds are added by the caller.
void addTransferResults(RunReport& report, const TransferOptions& options,
                        const acoustics::TransferResult& result);

}  // namespace fluidsound::tools
