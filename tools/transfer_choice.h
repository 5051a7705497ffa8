// tools/transfer_choice.h — which transfer model a `transfer` or `run` stage runs: the
// `--transfer image|geometric` option over the scene's "transfer" block (docs/cli.md,
// docs/scene.md), with the geometric model's settings resolved over its defaults.
#pragma once

#include <optional>
#include <string>

#include "acoustics/transfer/geometric_transfer.h"
#include "sim/scene.h"

namespace CLI {
class App;
}

namespace fluidsound::tools {

/// Adds `--transfer image|geometric` to a subcommand; `model` stays empty unless it is given. An
/// unknown name is a usage error naming the option (exit 2).
void addTransferModelOption(CLI::App& command, std::optional<sim::TransferModel>& model);

/// The model a transfer stage runs and the geometric model's settings.
struct TransferChoice {
  sim::TransferModel model = sim::TransferModel::Geometric;
  /// The scene's max_bands and loss_factor over GeometricTransferOptions' defaults; unused by
  /// the image-source model.
  acoustics::GeometricTransferOptions geometric;
};

/// @brief The option's model if given, else the scene's, with the scene's geometric settings.
TransferChoice transferChoice(const sim::Scene& scene,
                              const std::optional<sim::TransferModel>& option);

/// "geometric" or "image", as the scene field and the option spell it.
std::string transferModelName(sim::TransferModel model);

/// The choice as text, for `run`'s input fingerprint of the transfer stage: the model, and for
/// the geometric model every setting (a changed model or setting runs transfer again).
std::string transferChoiceFingerprint(const TransferChoice& choice);

}  // namespace fluidsound::tools
