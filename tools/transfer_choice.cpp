// tools/transfer_choice.cpp — see transfer_choice.h.
#include "tools/transfer_choice.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <map>

namespace fluidsound::tools {

void addTransferModelOption(CLI::App& command, std::optional<sim::TransferModel>& model) {
  const std::map<std::string, sim::TransferModel> names{
      {"geometric", sim::TransferModel::Geometric}, {"image", sim::TransferModel::Image}};
  command
      .add_option_function<std::string>(
          "--transfer", [&model, names](const std::string& name) { model = names.at(name); },
          "transfer model: geometric (each frame's liquid and solids) or image (image source "
          "under a flat surface); default: the scene's transfer.model, else image")
      ->check(CLI::IsMember({"geometric", "image"}));
}

TransferChoice transferChoice(const sim::Scene& scene,
                              const std::optional<sim::TransferModel>& option) {
  TransferChoice choice;
  choice.model = option.value_or(scene.transfer.model);
  if (scene.transfer.maxBands) choice.geometric.maxBands = *scene.transfer.maxBands;
  if (scene.transfer.lossFactor) choice.geometric.lossFactor = *scene.transfer.lossFactor;
  if (scene.transfer.maxFrequency) choice.geometric.maxFrequency = *scene.transfer.maxFrequency;
  if (scene.transfer.air == sim::AirModel::Wave) {
    acoustics::WaveAirOptions& air = choice.geometric.waveAir.emplace();
    if (scene.transfer.airInterval) air.interval = *scene.transfer.airInterval;
    if (scene.transfer.airCell) air.cellSize = *scene.transfer.airCell;
  }
  return choice;
}

std::string transferModelName(sim::TransferModel model) {
  return model == sim::TransferModel::Image ? "image" : "geometric";
}

std::string transferChoiceFingerprint(const TransferChoice& choice) {
  if (choice.model == sim::TransferModel::Image) return "transfer image";
  const acoustics::GeometricTransferOptions& g = choice.geometric;
  char text[320];
  std::snprintf(text, sizeof text,
                "transfer geometric max-bands %d loss-factor %.17g band-phase %.17g "
                "max-frequency %.17g air %s interval %.17g cell %.17g ring %.17g layer %d",
                g.maxBands, g.lossFactor, g.bandPhaseFactor, g.maxFrequency,
                g.waveAir ? "wave" : "rigid_surface", g.waveAir ? g.waveAir->interval : 0.0,
                g.waveAir ? g.waveAir->cellSize : 0.0, g.waveAir ? g.waveAir->ringTime : 0.0,
                g.waveAir ? g.waveAir->absorbingCells : 0);
  return text;
}

}  // namespace fluidsound::tools
