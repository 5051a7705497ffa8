// tools/transfer_command.h — `fluidsound transfer SCENE.json -o OUTDIR`: fills the `transfer`
// values of OUTDIR/bubbles.json from the artefacts alone (frames/NNNN.vdb, the scene's listeners),
// with the image-source model (acoustics/image_source_transfer.h; docs/transfer.md).
#pragma once

#include <string>

#include "tools/command_options.h"

namespace fluidsound::tools {

struct TransferOptions {
  CommonOptions common;
  std::string scene;
  std::string output;
};

CLI::App* addTransferCommand(CLI::App& app, TransferOptions& options);
int runTransferCommand(const TransferOptions& options);

}  // namespace fluidsound::tools
