// tests/sim/fluid_solver_substeps_test.cpp — the substep cap of FluidSolver::advanceTo: a frame
// that would need more substeps than the limit stops with a SubstepLimitError naming the likely
// scene fields, before the first substep beyond it, instead of running (nearly) forever. The
// scenes are built in code, past the scene reader's own checks (io/scene_file.cpp), as a scene
// whose flow blows up would reach the solver.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "sim/fluid/fluid_solver.h"
#include "support/small_tank.h"

namespace fluidsound::sim {
namespace {

/// A closed 8 × 8 × 8 tank of 1 cm cells, half full: a few thousand particles, fast substeps.
Scene smallTank() { return test::smallTank({0.08, 0.04, 0.08}, 1.0); }

/// The SubstepLimitError of advancing `scene` one frame (1/30 s) with at most `limit` substeps,
/// or a test failure.
SubstepLimitError limitErrorOf(const Scene& scene, int limit) {
  FluidSolver solver(scene);
  solver.limitSubstepsPerFrame(limit);
  try {
    solver.advanceTo(1.0 / 30.0);
  } catch (const SubstepLimitError& error) {
    EXPECT_LT(solver.time(), 1.0 / 30.0) << "the frame was not stopped";
    return error;
  }
  ADD_FAILURE() << "no SubstepLimitError";
  return SubstepLimitError("", "");
}

// Claim: CFL 1e-12 (a step of 1e-14 s: 3·10¹² substeps per frame) stops at the limit, naming the
// limit, the frame's end and time.cfl, in one line.
TEST(FluidSolverSubsteps, TinyCflStopsAtTheLimitNamingCfl) {
  Scene scene = smallTank();
  scene.time.cfl = 1e-12;
  const auto start = std::chrono::steady_clock::now();
  const SubstepLimitError error = limitErrorOf(scene, 20);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string message = error.what();
  EXPECT_NE(message.find("more than 20 substeps for the frame ending at 0.0333333 s"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("cfl 1e-12"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(error.likelyFields(), "time.cfl") << message;
  EXPECT_LT(seconds, 2.0) << "20 substeps of an 8³ grid should take well under a second";
}

// Claim: an emitter at 10⁶ m/s makes the emitter's speed the likely field.
TEST(FluidSolverSubsteps, FastEmitterIsNamed) {
  Scene scene = smallTank();
  scene.emitters.push_back({{0.04, 0.07, 0.04}, {0, -1, 0}, 0.01, 1e6, 0.0, 1.0});
  const SubstepLimitError error = limitErrorOf(scene, 5);
  EXPECT_EQ(error.likelyFields(), "emitters[].speed, time.cfl") << error.what();
  EXPECT_NE(std::string(error.what()).find("emitters 1e+06 m/s"), std::string::npos)
      << error.what();
}

// Claim: gravity of 10³⁰ m/s² makes gravity the likely field (its margin √(5 h |g|) ≈ 2·10¹⁴ m/s).
TEST(FluidSolverSubsteps, HugeGravityIsNamed) {
  Scene scene = smallTank();
  scene.gravity = {0, -1e30, 0};
  const SubstepLimitError error = limitErrorOf(scene, 5);
  EXPECT_EQ(error.likelyFields(), "gravity, time.cfl") << error.what();
}

// Claim: a frame within the limit is not stopped: at rest under gravity, a 1/30 s frame of 1 cm
// cells at CFL 1 needs ceil((1/30) / (0.01 / √(5·0.01·9.81))) = 3 substeps, so a limit of 3
// passes and the substeps are counted.
TEST(FluidSolverSubsteps, FrameWithinTheLimitRunsToItsEnd) {
  FluidSolver solver(smallTank());
  solver.limitSubstepsPerFrame(3);
  const FrameStats stats = solver.advanceTo(1.0 / 30.0);
  EXPECT_LE(stats.substeps, 3);
  EXPECT_GE(stats.substeps, 1);
  EXPECT_DOUBLE_EQ(solver.time(), 1.0 / 30.0);
}

}  // namespace
}  // namespace fluidsound::sim
