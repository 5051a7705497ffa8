// tests/support/small_tank.h — the solver tests' smallest scene: a closed 8 × 8 × 8 box of 1 cm
// cells with a box of liquid on its floor: a few thousand particles, fast substeps.
#pragma once

#include "sim/scene.h"

namespace fluidsound::test {

/// @param liquidMax  the liquid box's far corner [m] (its near corner is the origin)
/// @param duration   the scene's length [s]
inline sim::Scene smallTank(const Vec3& liquidMax, double duration) {
  sim::Scene scene;
  scene.domain.max = {0.08, 0.08, 0.08};
  scene.domain.cell = 0.01;
  scene.time.duration = duration;
  scene.liquid.push_back({sim::Box{{0, 0, 0}, liquidMax}, {}});
  return scene;
}

}  // namespace fluidsound::test
