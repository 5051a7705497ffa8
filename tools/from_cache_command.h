// tools/from_cache_command.h — `fluidsound from-cache CACHE.json -o OUTDIR`: the sound of a liquid
// simulated elsewhere (a Houdini or Blender OpenVDB cache, or fluidsound's own frames; issue 21,
// docs/import.md): the bubble model at the cache's rate (sim::cacheBubbles), then the transfer and
// synth stages as `run` has them, writing what `run` writes. This command only wires files to them.
#pragma once

#include <optional>
#include <string>

#include "acoustics/bubble/oscillator_model.h"
#include "sim/scene.h"
#include "tools/audio_options.h"
#include "tools/command_options.h"

namespace fluidsound::tools {

struct FromCacheOptions {
  CommonOptions common;
  std::string cache;
  std::string output;
  AudioOutputOptions audio;
  acoustics::OscillatorModel model;
  std::optional<sim::TransferModel> transfer;  ///< --transfer; empty: the cache's transfer.model
};

CLI::App* addFromCacheCommand(CLI::App& app, FromCacheOptions& options);
int runFromCacheCommand(const FromCacheOptions& options);

}  // namespace fluidsound::tools
