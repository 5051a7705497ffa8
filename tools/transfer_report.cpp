// tools/transfer_report.cpp — see transfer_report.h.
#include "tools/transfer_report.h"

#include <nlohmann/json.hpp>

namespace fluidsound::tools {
namespace {

/// The geometric model's solver statistics as report.json's results.geometric (docs/cli.md).
nlohmann::ordered_json geometricStats(const acoustics::GeometricTransferStats& s) {
  return {
      {"reciprocal_frames", s.reciprocalFrames}, {"adjoint_frames", s.adjointFrames},
      {"widened_frames", s.widenedFrames},       {"mode_limited_frames", s.modeLimitedFrames},
      {"bands", s.bands},                        {"modes", s.modes},
      {"factorisations", s.factorisations},      {"solves", s.solves},
      {"max_unknowns", s.maxUnknowns},           {"samples_outside_liquid", s.samplesOutsideLiquid},
      {"samples_above_limit", s.samplesAboveLimit}, {"air_solves", s.airSolves},
      {"air_samples", s.airSamples},            {"air_seconds", s.airSeconds},
      {"air_megabytes", static_cast<double>(s.airBytes) / 1e6}, {"rings", s.rings},
      {"max_frequency_hz", s.maxFrequency},      {"solve_seconds", s.solveSeconds}};
}

}  // namespace

void addTransferResults(RunReport& report, const TransferOptions& o, const TransferChoice& choice,
                        const acoustics::TransferResult& result) {
  report.setting("scene", o.scene);
  report.setting("output", o.output);
  report.setting("model", transferModelName(choice.model));
  if (choice.model == sim::TransferModel::Geometric) {
    report.setting("max_bands", choice.geometric.maxBands);
    report.setting("loss_factor", choice.geometric.lossFactor);
    report.setting("band_phase_factor", choice.geometric.bandPhaseFactor);
    report.setting("max_frequency_hz", choice.geometric.maxFrequency);
    report.setting("air", choice.geometric.waveAir ? "wave" : "rigid_surface");
    if (choice.geometric.waveAir) {
      report.setting("air_interval", choice.geometric.waveAir->interval);
      report.setting("air_cell", choice.geometric.waveAir->cellSize);
    }
  }
  report.setOscillatorModel(o.model);
  report.result("bubbles", static_cast<double>(result.bubbles));
  report.result("samples", static_cast<double>(result.samples));
  report.result("frames_read", static_cast<double>(result.framesRead));
  if (choice.model == sim::TransferModel::Geometric)
    report.resultJson("geometric", geometricStats(result.geometric).dump());
  report.stageSeconds("transfer", result.seconds);
}

nlohmann::ordered_json transferSummary(const nlohmann::ordered_json& transferReport) {
  nlohmann::ordered_json summary = nlohmann::ordered_json::object();
  if (!transferReport.is_object()) return summary;
  const nlohmann::ordered_json settings =
      transferReport.value("settings", nlohmann::ordered_json::object());
  for (const char* key : {"model", "max_bands", "loss_factor", "band_phase_factor"})
    if (settings.contains(key)) summary[key] = settings[key];
  const nlohmann::ordered_json results =
      transferReport.value("results", nlohmann::ordered_json::object());
  if (results.contains("geometric")) summary["geometric"] = results["geometric"];
  return summary;
}

}  // namespace fluidsound::tools
