// sim/fluid/mac_velocity.h — velocity on a staggered (MAC) grid: each component on the faces normal
// to it (Harlow & Welch 1965), in m/s.
#pragma once

#include <array>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"

namespace fluidsound::sim {

/// Face velocities [m/s]: component[0] = u on x-faces (ni+1, nj, nk), [1] = v on y-faces,
/// [2] = w on z-faces. See GridGeometry for face positions.
struct MacVelocity {
  std::array<Array3f, 3> component;

  MacVelocity() = default;
  explicit MacVelocity(const GridGeometry& g)
      : component{Array3f(g.faceCount(0)), Array3f(g.faceCount(1)), Array3f(g.faceCount(2))} {}

  Array3f& operator[](int axis) { return component[axis]; }
  const Array3f& operator[](int axis) const { return component[axis]; }
};

}  // namespace fluidsound::sim
