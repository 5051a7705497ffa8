// tools/transfer_report.cpp — see transfer_report.h.
#include "tools/transfer_report.h"

namespace fluidsound::tools {

void addTransferResults(RunReport& report, const TransferOptions& o,
                        const acoustics::TransferResult& result) {
  report.setting("scene", o.scene);
  report.setting("output", o.output);
  report.setting("model", "image source, locally flat surface (docs/transfer.md)");
  report.setOscillatorModel(o.model);
  report.result("bubbles", static_cast<double>(result.bubbles));
  report.result("samples", static_cast<double>(result.samples));
  report.result("frames_read", static_cast<double>(result.framesRead));
  report.stageSeconds("transfer", result.seconds);
}

}  // namespace fluidsound::tools
