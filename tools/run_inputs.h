// tools/run_inputs.h — what `run` reads and writes in OUTDIR, named before the first stage: the
// inputs' fingerprint, the frame files, the audio file's name, and the check that every file
// it writes can be written.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sim/scene.h"
#include "tools/audio_options.h"

namespace fluidsound::tools {

/// The bytes of a file; empty if it cannot be read.
std::string fileBytes(const std::filesystem::path& path);

/// The inputs' fingerprint: the scene file, the grid cell size it runs at (the file's or
/// --cell's), every mesh it names and the program's version.
std::string inputHash(const sim::Scene& scene);

/// The frames simulate writes for `run` (all of them, VDB only), named relative to OUTDIR.
std::vector<std::string> frameFiles(const sim::Scene& scene);

/// The name of the audio file: the scene file's name without `.json` and `.scene`, with the
/// extension of the format asked for (`.wav` by default).
std::string audioName(const std::filesystem::path& scene, const AudioOutputOptions& audio);

/// Checks, before the first frame, that each file the run writes into an existing OUTDIR could be
/// written (a new OUTDIR is made by simulate), so that no later stage fails on it after the
/// simulation.
void requireRunOutputs(const std::filesystem::path& out, const std::string& audio);

}  // namespace fluidsound::tools
