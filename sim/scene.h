// sim/scene.h — a scene (`fluidsound.scene/1`, DESIGN.md; docs/scene.md) as value types: what
// the simulation reads (the liquid solver's part, sim/fluid/fluid_scene.h, and the bubble model's)
// and what the later stages read (listeners, audio rate). io/scene_file.h parses and validates the
// JSON into these records.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sim/bubbles/bubble_settings.h"
#include "sim/fluid/fluid_scene.h"

namespace fluidsound::sim {

/// A listener: one output channel.
struct Listener {
  std::string name;
  Vec3 position{};  ///< [m]
  bool operator==(const Listener&) const = default;
};

/// A whole scene: the fluid's part and the rest.
struct Scene : FluidScene {
  std::filesystem::path file;       ///< the scene file (for messages); paths inside are resolved
  std::vector<Listener> listeners;  ///< default: one listener 0.5 m above the domain centre
  double sampleRate = 48000.0;      ///< [Hz], the "audio" block
  BubbleSettings bubbles;           ///< the "bubbles" block (docs/bubbles.md); defaults if absent
  bool operator==(const Scene&) const = default;
};

}  // namespace fluidsound::sim
