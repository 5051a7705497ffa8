// sim/liquid_frame.h — one frame of a liquid simulated elsewhere (a Houdini or Blender cache, or
// fluidsound's own frames) as the bubble model reads it at the cache's rate (issue 21;
// docs/import.md): sampled on the bubble model's grid, in metres with y up.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sim/fluid/array3.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particles.h"

namespace fluidsound::sim {

/// A frame's particles [m, m/s], one entry per particle in each array but `id`.
struct FrameParticles {
  std::vector<Vec3f> position;
  std::vector<Vec3f> velocity;
  /// One per particle, unique, stable from frame to frame; empty when the cache has no ids (the
  /// import matches particles by their advected positions instead).
  std::vector<std::uint64_t> id;
  std::size_t size() const { return position.size(); }
};

/// One frame on the import's grid.
struct LiquidFrame {
  double time = 0.0;        ///< [s] from the cache's first frame
  /// The cache's level set at cell centres [m], negative in the liquid (a band field is fine): the
  /// surface the transfer stage reads. The bubble model makes its own from the particles.
  Array3f liquidDistance;
  MacVelocity velocity;     ///< the liquid's velocity on the faces [m/s]
  /// Per axis, 1 where the cache gives the face's velocity; the import extends the velocity beyond
  /// them as the solver does (velocity_extrapolation.h). Empty arrays: every face is known.
  std::array<Array3<std::uint8_t>, 3> velocityKnown;
  FrameParticles particles;
};

}  // namespace fluidsound::sim
