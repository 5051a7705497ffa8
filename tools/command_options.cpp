// tools/command_options.cpp — shared subcommand options (see command_options.h).
#include "tools/command_options.h"

#include <map>
#include <string>

#include <CLI/CLI.hpp>

namespace fluidsound::tools {

void addCommonOptions(CLI::App& command, CommonOptions& options) {
  command.add_option("--threads", options.threads, "worker threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  command.add_flag("--quiet,-q", options.quiet, "no progress display and no notes");
}

void addOscillatorModelOptions(CLI::App& command, acoustics::OscillatorModel& model) {
  using namespace acoustics;
  const std::map<std::string, DampingModel> damping{{"devin", DampingModel::Devin},
                                                    {"vandendoel", DampingModel::VanDenDoel}};
  const std::map<std::string, ExcitationModel> excitation{
      {"jet", ExcitationModel::NeckCollapseJet},
      {"displacement", ExcitationModel::InitialDisplacement}};
  command.add_flag_callback(
      "--thermal", [&model] { model.polytropic = PolytropicModel::Thermal; },
      "thermal effective polytropic index (Prosperetti) instead of adiabatic");
  command.add_flag("--vapour", model.vapour, "include the vapour pressure in the restoring term");
  command.add_flag("--hydrostatic", model.hydrostatic, "ambient pressure p0 + rho g h at the bubble's depth");
  command.add_option("--damping", model.damping, "damping model: devin (default) or vandendoel")
      ->transform(CLI::CheckedTransformer(damping, CLI::ignore_case));
  command.add_option("--excitation", model.excitation, "excitation: jet (default) or displacement")
      ->transform(CLI::CheckedTransformer(excitation, CLI::ignore_case));
  command.add_option("--displacement", model.initialDisplacement,
                     "initial radial displacement epsilon for --excitation displacement")
      ->check(CLI::PositiveNumber);
  command.add_flag("--chirp", model.chirp, "van den Doel rising pitch f0 (1 + xi beta t)");
  command.add_option("--chirp-rise", model.chirpRiseFactor, "van den Doel rise factor xi (default 0.1)")
      ->check(CLI::NonNegativeNumber);
}

}  // namespace fluidsound::tools
