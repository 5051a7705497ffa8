// tools/body_modes.h — a scene body's modal model for `run` (docs/solids.md, "Bodies in run"): its
// shape in its rigid-body frame (sim::rigidBodySpec) as voxels, its modes by acoustics::analyseModes,
// read from and written to a cache folder (io/modal_model_file.h) under a key of its shape and
// every setting that shapes the modes.
#pragma once

#include <filesystem>
#include <string>

#include "acoustics/modal/modal_analysis.h"
#include "sim/scene.h"

namespace fluidsound::tools {

/// A body's modes and where they came from.
struct BodyModes {
  acoustics::ModalModel model;
  std::size_t voxels = 0;
  double voxelSize = 0.0;  ///< [m]
  std::string cache;       ///< "read", "written" or "not written: WHY"
  double seconds = 0.0;    ///< of the analysis or the read
};

/// @brief The free body's modes below `maxFrequency` [Hz] (at most 200), from the cache when a
///        file of its key is there.
/// @param index  the body's place in the scene (for messages: `bodies[i].resolution`)
/// @throws io::InputError naming the scene file and `bodies[i].resolution` when no voxel lies
///         inside the body at its resolution
BodyModes bodyModes(const sim::Scene& scene, std::size_t index, const std::filesystem::path& cacheFolder,
                    double maxFrequency);

}  // namespace fluidsound::tools
