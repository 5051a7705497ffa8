// sim/particle_paths.h — where a cache's particle is between two frames (issue 21;
// docs/import.md): the cubic Hermite curve through its positions in both frames with its
// velocities there as end tangents — the sub-frame interpolation of particle caches (Houdini's
// velocity-based retiming does the same). A particle falling onto the surface keeps its speed
// until it strikes it, as in the solver, instead of crossing the surface at its mean speed over
// the frame on a straight line.
#pragma once

#include "sim/fluid/particles.h"

namespace fluidsound::sim {

/// A particle's place [m] and velocity [m/s] on its path.
struct PathPoint {
  Vec3f position;
  Vec3f velocity;
};

/// @brief The point at fraction s ∈ [0, 1] of the interval [s] from (x0, v0) to (x1, v1):
///        x(s) = h00·x0 + h10·T·v0 + h01·x1 + h11·T·v1 with the Hermite basis, v = dx/dt.
///        s = 0 gives (x0, v0) and s = 1 gives (x1, v1).
PathPoint hermitePath(const Vec3f& x0, const Vec3f& v0, const Vec3f& x1, const Vec3f& v1, double interval,
                      double s);

}  // namespace fluidsound::sim
