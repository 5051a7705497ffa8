// tools/main.cpp — the `fluidsound` command: parses the command line (CLI11), sets the thread
// limit, runs one subcommand and turns every failure into one line and an exit code (docs/cli.md).
#include <cstdio>
#include <exception>
#include <optional>

#include <CLI/CLI.hpp>
#include <oneapi/tbb/global_control.h>

#include "acoustics/transfer/transfer_stage.h"
#include "io/input_error.h"
#include "io/interruption.h"
#include "sim/fluid/simulation_failure.h"
#include "tools/from_cache_command.h"
#include "tools/run_command.h"
#include "tools/run_report.h"
#include "tools/simulate_command.h"
#include "tools/modes_command.h"
#include "tools/spectrogram_command.h"
#include "tools/synth_command.h"
#include "tools/transfer_command.h"
#include "tools/validate_command.h"

using namespace fluidsound::tools;

namespace {

int runWithThreads(int threads, const auto& command) {
  // The only place that limits TBB's threads (docs/cli.md: --threads N, 0 = all cores).
  std::optional<oneapi::tbb::global_control> limit;
  if (threads > 0)
    limit.emplace(oneapi::tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  const int code = command();
  // A signal no loop saw (a short command, the last step): the outputs are whole, but the
  // command still ends as interrupted.
  fluidsound::io::throwIfInterrupted("the end, every output written");
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fluidsound — the sound of liquids from physics (Harmonic Fluids, Zheng & James 2009)"};
  app.set_version_flag("--version", versionText());
  app.require_subcommand(1);
  SynthOptions synth;
  SpectrogramOptions spectrogram;
  ValidateOptions validate;
  SimulateOptions simulate;
  TransferOptions transfer;
  RunOptions run;
  FromCacheOptions fromCache;
  ModesOptions modes;
  CLI::App* synthCommand = addSynthCommand(app, synth);
  CLI::App* spectrogramCommand = addSpectrogramCommand(app, spectrogram);
  CLI::App* validateCommand = addValidateCommand(app, validate);
  CLI::App* simulateCommand = addSimulateCommand(app, simulate);
  CLI::App* transferCommand = addTransferCommand(app, transfer);
  CLI::App* runCommand = addRunCommand(app, run);
  CLI::App* fromCacheCommand = addFromCacheCommand(app, fromCache);
  CLI::App* modesCommand = addModesCommand(app, modes);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "fluidsound: error: %s\n", e.what());
    std::fprintf(stderr, "  (see fluidsound %s--help)\n",
                 app.get_subcommands().empty() ? "" : (app.get_subcommands().front()->get_name() + " ").c_str());
    return kExitUsage;
  }

  // SIGINT and SIGTERM from here on end the command through io::Interrupted (docs/cli.md).
  fluidsound::io::installInterruptionHandlers();
  try {
    if (synthCommand->parsed())
      return runWithThreads(synth.common.threads, [&] { return runSynthCommand(synth); });
    if (spectrogramCommand->parsed())
      return runWithThreads(spectrogram.common.threads, [&] { return runSpectrogramCommand(spectrogram); });
    if (validateCommand->parsed())
      return runWithThreads(validate.common.threads, [&] { return runValidateCommand(validate); });
    if (simulateCommand->parsed())
      return runWithThreads(simulate.common.threads, [&] { return runSimulateCommand(simulate); });
    if (runCommand->parsed()) return runWithThreads(run.common.threads, [&] { return runRunCommand(run); });
    if (modesCommand->parsed()) return runWithThreads(modes.common.threads, [&] { return runModesCommand(modes); });
    if (fromCacheCommand->parsed())
      return runWithThreads(fromCache.common.threads, [&] { return runFromCacheCommand(fromCache); });
    if (transferCommand->parsed())
      return runWithThreads(transfer.common.threads, [&] { return runTransferCommand(transfer); });
  } catch (const fluidsound::io::Interrupted& e) {
    std::fprintf(stderr, "fluidsound: %s\n", e.what());
    return e.exitCode();
  } catch (const fluidsound::io::InputError& e) {
    std::fprintf(stderr, "fluidsound: error: %s\n", e.what());
    return kExitBadInput;
  } catch (const CLI::ValidationError& e) {
    std::fprintf(stderr, "fluidsound: error: %s\n", e.what());
    return kExitUsage;
  } catch (const fluidsound::io::OutputError& e) {
    std::fprintf(stderr, "fluidsound: error: %s\n", e.what());
    return kExitOutputFailed;
  } catch (const fluidsound::sim::SimulationFailure& e) {
    std::fprintf(stderr, "fluidsound: simulation failed: %s\n", e.what());
    return kExitSimulationFailed;
  } catch (const fluidsound::acoustics::TransferSolveError& e) {
    std::fprintf(stderr, "fluidsound: transfer failed: %s\n", e.what());
    return kExitSimulationFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fluidsound: internal error: %s\n", e.what());
    return kExitInternal;
  }
  return kExitUsage;
}
