// tests/sim/fluid/simulation_failure_test.cpp — the checks that stop a simulation whose velocities
// stopped being numbers: each names the time and the place, one line, and passes any finite state.
#include "sim/fluid/simulation_failure.h"

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "support/command_runner.h"
#include "support/temp_folder.h"

namespace fluidsound::sim {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

Particles threeParticles() {
  Particles p;
  p.push({0.01f, 0.02f, 0.03f}, {1.0f, -2.0f, 0.5f});
  p.push({0.0945f, 0.0253f, 0.1062f}, {3.0f, 0.0f, 0.0f});
  p.push({0.05f, 0.05f, 0.05f}, {0.0f, 0.0f, 0.0f});
  p.id = {7, 8, 9};
  return p;
}

/// The message of the SimulationFailure `check` throws, or "" if it throws none.
template <typename Check>
std::string failureOf(Check check) {
  try {
    check();
  } catch (const SimulationFailure& e) {
    return e.what();
  }
  return "";
}

// Claim: finite velocities pass; a NaN or ∞ component of any particle stops the run, naming the
// particle's id, its position to 0.1 mm and the time. Reference: the values put in.
TEST(SimulationFailure, ANonFiniteParticleVelocityIsNamedWithItsPosition) {
  Particles p = threeParticles();
  EXPECT_EQ(failureOf([&] { requireFiniteParticleVelocities(p, 0.1); }), "");
  p.velocity[1][2] = std::numeric_limits<float>::quiet_NaN();
  p.velocity[2][0] = kInfinity;  // a later one: the first in storage order is named
  const std::string message = failureOf([&] { requireFiniteParticleVelocities(p, 0.172384); });
  EXPECT_NE(message.find("t = 0.172384 s"), std::string::npos) << message;
  EXPECT_NE(message.find("particle 8 at (0.0945, 0.0253, 0.1062) m"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// Claim: a face velocity that is ∞ is named by its axis, index and centre. Reference: the y-face
// (3, 4, 5) of a 1 cm grid lies at x = 3.5 cm, y = 4 cm, z = 5.5 cm.
TEST(SimulationFailure, ANonFiniteFaceVelocityIsNamedWithItsFace) {
  GridGeometry g;
  g.cells = {8, 8, 8};
  g.cellSize = 0.01;
  MacVelocity u(g);
  EXPECT_EQ(failureOf([&] { requireFiniteFaceVelocities(u, g, 0.5, "pressure projection"); }), "");
  u[1](3, 4, 5) = -kInfinity;
  const std::string message =
      failureOf([&] { requireFiniteFaceVelocities(u, g, 0.5, "pressure projection"); });
  EXPECT_NE(message.find("after the pressure projection"), std::string::npos) << message;
  EXPECT_NE(message.find("y-face (3, 4, 5) at (0.0350, 0.0400, 0.0550) m"), std::string::npos)
      << message;
}

// Claim: a time step that does not advance the clock (0, or below its resolution at t = 1e3 s)
// stops the run naming the fastest particle; a positive step passes. Reference: the speeds put
// in (1e20 m/s: its float square is ∞, which made the solver's step 0 before this check).
TEST(SimulationFailure, ATimeStepThatDoesNotAdvanceTheClockIsNamedWithTheFastestParticle) {
  Particles p = threeParticles();
  EXPECT_EQ(failureOf([&] { requireTimeAdvances(p, 0.2, 1e-4); }), "");
  p.velocity[2] = {1e20f, 0.0f, 0.0f};
  const std::string zero = failureOf([&] { requireTimeAdvances(p, 0.2, 0.0); });
  EXPECT_NE(zero.find("particle 9 at (0.0500, 0.0500, 0.0500) m moves at 1e+20 m/s"),
            std::string::npos)
      << zero;
  EXPECT_NE(failureOf([&] { requireTimeAdvances(p, 1e3, 1e-14); }), "");
}

// Claim: the scene that first reached the solver's blow-up from input (an emitter at 1e30 m/s,
// whose particles' float speed squares are infinite; before the checks of this file it ended in
// "internal error: pressure projection: … dt 0.000000 s", exit 5) is now refused when the scene
// is read (emitter speeds are bounded, docs/scene.md): exit 3 naming emitters[0].speed, nothing
// written. Exit 6 is left for a solver that blows up on valid input (the unit tests above).
TEST(SimulationFailure, TheSceneThatBlewTheSolverUpIsRefusedAsBadInput) {
  test::TempFolder folder;
  const auto scene = folder.path() / "fast.scene.json";
  std::ofstream(scene) << R"({
  "format": "fluidsound.scene/1",
  "domain": { "min": [0, 0, 0], "max": [0.1, 0.1, 0.1], "cell": 0.01 },
  "time": { "duration": 0.1, "fps": 30 },
  "emitters": [ { "disk": { "center": [0.05, 0.09, 0.05], "normal": [0, -1, 0], "radius": 0.01 },
                  "speed": 1e30, "start": 0, "end": 0.1 } ],
  "listeners": [ { "name": "above", "position": [0.05, 0.5, 0.05] } ]
})";
  const auto out = folder.path() / "out";
  const test::CommandOutcome run =
      test::runFluidsound({"simulate", scene.string(), "-o", out.string(), "--quiet"});
  EXPECT_EQ(run.exitCode, 3) << run.err;
  EXPECT_NE(run.err.find("emitters[0].speed"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace fluidsound::sim
