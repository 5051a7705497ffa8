// tests/sim/bubbles/bubble_model_test.cpp — the bubble model stage on hand-made liquid states: a resting
// tank makes no bubble; a jet driven through the surface makes bubbles, more with more flux;
// bubbles are never born in air or in a solid; birth times are spread continuously inside the
// steps; a bubble rises at its terminal speed and ends at the surface when that speed predicts;
// the result is the same bit for bit on 1 and 2 threads; bad settings name their field.
#include "sim/bubbles/bubble_model.h"

#include <gtest/gtest.h>

#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/fluid/particle_seeding.h"
#include "support/synthetic_tank.h"

namespace fluidsound::sim {
namespace {

using test::Jet;
using test::SyntheticTank;

constexpr int kCells = 24;           // 12 cm tank of 5 mm cells
constexpr double kCell = 0.005;      // h [m]
constexpr double kSurface = 0.08;    // free surface height [m]
constexpr std::uint64_t kSeed = 2009;
const Vec3 kGravity{0.0, -9.81, 0.0};  // [m/s²] (physics.md §2)

/// Everything a jet run produced.
struct JetRun {
  std::vector<BubbleHistory> bubbles;
  std::vector<BubbleStepReport> reports;
  std::vector<double> stepStart, stepLength;  ///< [s] per step
  SpawnCounts totals;
};

struct JetRunOptions {
  Jet jet;
  BubbleSettings settings;
  double duration = 0.3;                  ///< [s]
  std::vector<double> steps{1.0 / 600};   ///< substep lengths [s], used in turn
  std::optional<Box> solidBox;
  bool gridJet = true;           ///< the grid moves with the jet below the surface
  std::optional<double> gridJetSpeed;  ///< the grid's jet speed [m/s] if not the particles'
  bool reverseEachStep = false;  ///< reverse the particle arrays before each step
  int stepsPerFrame = 10;
};

JetRun runJet(const JetRunOptions& o) {
  SyntheticTank tank(kCells, kCell, kSurface, kSeed, o.solidBox);
  if (o.gridJet) {
    Jet grid = o.jet;
    grid.speed = o.gridJetSpeed.value_or(o.jet.speed);
    tank.setJetGridVelocity(grid, grid.bottom, kSurface);
  }
  BubbleModel model(o.settings, kSeed, kGravity);
  JetRun run;
  double t = 0.0;
  for (std::size_t n = 0; t < o.duration; ++n) {
    const double dt = o.steps[n % o.steps.size()];
    tank.driveJet(o.jet, dt);
    if (o.reverseEachStep) {
      std::reverse(tank.positions().begin(), tank.positions().end());
      std::reverse(tank.velocities().begin(), tank.velocities().end());
      std::reverse(tank.ids().begin(), tank.ids().end());
    }
    run.reports.push_back(model.step(tank.state(), t, dt));
    run.stepStart.push_back(t);
    run.stepLength.push_back(dt);
    t += dt;
    if ((n + 1) % o.stepsPerFrame == 0) model.sampleFrame(t);
  }
  run.bubbles = model.bubbles();
  run.totals = model.totalSpawnCounts();
  return run;
}

void printTotals(const char* label, const JetRun& run) {
  const SpawnCounts& c = run.totals;
  std::cout << "[ measured ] " << label << ": attempts " << c.attempts << ", created " << c.created
            << ", rejected outside/solid/air/sparse " << c.rejectedOutside << "/" << c.rejectedSolid << "/"
            << c.rejectedAir << "/" << c.rejectedSparse << "\n";
}

TEST(BubbleModel, StillTankMakesNoBubble) {
  // Claim: a tank at rest for 2 s — flat surface, particles jiggling by ±0.05 h about their rest
  // positions with spurious velocities up to 1 cm/s per axis (a resting FLIP tank's noise) — makes
  // no seed and no bubble. Reference: entrainment needs 2 h of depth growth within 20 ms (0.5 m/s)
  // or 1 m/s into the liquid; the noise is 40× and 60× below. Tolerance: exactly zero (a count).
  constexpr double h = 0.01;
  SyntheticTank tank(12, h, kSurface, kSeed);
  const std::vector<Vec3f> rest = tank.positions();
  BubbleModel model(BubbleSettings{}, kSeed, kGravity);
  const double dt = 1.0 / 300;
  std::size_t tagged = 0, seeds = 0, attempts = 0;
  double t = 0.0;
  for (int n = 0; n < 600; ++n, t += dt) {
    tank.jiggle(rest, 0.05 * h, 0.01);
    const BubbleStepReport r = model.step(tank.state(), t, dt);
    tagged += r.taggedParticles;
    seeds += r.newSeeds;
    attempts += r.spawn.attempts;
    if ((n + 1) % 10 == 0) model.sampleFrame(t + dt);
  }
  std::cout << "[ measured ] 2 s at rest: " << tagged / 600 << " tagged particles per step, " << seeds
            << " seeds, " << attempts << " attempts, " << model.bubbles().size() << " bubbles\n";
  EXPECT_GT(tagged, 0u) << "the band must hold particles, or the test checks nothing";
  EXPECT_EQ(seeds, 0u);
  EXPECT_EQ(attempts, 0u);
  EXPECT_TRUE(model.bubbles().empty());
}

TEST(BubbleModel, MoreFluxThroughTheSurfaceMakesMoreBubbles) {
  // Claim: a jet driving particles down through the surface at 0.75, 1.5 and 3 m/s (fluxes in
  // ratio 1 : 2 : 4) makes bubbles, and more with more flux. Reference: seeds are made at the
  // particle flux, so the Poisson mean of the attempts grows in proportion. Tolerance: each count
  // exceeds the previous by more than 3 standard deviations of the difference of two Poisson
  // counts, 3√(N₁ + N₂) (the runs are deterministic; the margin says the order is not luck).
  JetRunOptions o;
  o.settings.rate = 2.0;  // fewer bubbles than the default, to keep the test fast
  o.duration = 0.2;
  std::vector<std::size_t> created;
  for (const double speed : {0.75, 1.5, 3.0}) {
    o.jet.speed = speed;
    const JetRun run = runJet(o);
    printTotals(("jet " + std::to_string(speed) + " m/s").c_str(), run);
    created.push_back(run.totals.created);
  }
  EXPECT_GT(created[0], 20u);
  for (std::size_t i = 1; i < created.size(); ++i) {
    const double margin = 3.0 * std::sqrt(static_cast<double>(created[i] + created[i - 1]));
    EXPECT_GT(static_cast<double>(created[i]), created[i - 1] + margin)
        << "flux " << i << ": " << created[i] << " bubbles vs " << created[i - 1];
  }
}

TEST(BubbleModel, NeverCreatesABubbleInAirOrInASolid) {
  // Claim: density sampling never places a bubble in air or in a solid, although many attempts
  // land there: seeds lie up to a cell above the surface (a jet falling through it at 2 m/s into
  // still liquid) and against the face of a solid block beside the jet, and the sampling kernel is
  // a whole cell wide. Reference: the exact fields — φ = y − surface (linear, so interpolation is
  // exact) and the box's exact distance. Tolerance: none — every bubble's centre lies more than
  // its radius below the surface, outside the solid, and at least its radius from the solid as
  // the grid represents it (interpolated node distance, what the model can know).
  JetRunOptions o;
  o.jet.speed = 2.0;
  o.jet.top = kSurface + 3 * kCell;  // the jet starts in air
  o.gridJet = false;                 // the liquid beneath is still: the speed test marks seeds
  o.settings.jitterCells = 1.0;
  o.duration = 0.15;
  o.solidBox = Box{{0.075, 0.0, 0.0}, {0.12, 0.06, 0.12}};  // faces on grid nodes, touching the jet
  const JetRun run = runJet(o);
  printTotals("jet beside a block", run);
  EXPECT_GT(run.totals.rejectedAir, 0u) << "no attempt landed in air: the test would check nothing";
  EXPECT_GT(run.totals.rejectedSolid, 0u) << "no attempt landed in the solid: the test would check nothing";
  ASSERT_GT(run.bubbles.size(), 50u);
  const SyntheticTank reference(kCells, kCell, kSurface, kSeed, o.solidBox);
  const LiquidState fields = reference.state();
  for (const BubbleHistory& b : run.bubbles) {
    const Vec3& x = b.samples.front().position;
    EXPECT_LT(x[1], kSurface - b.radius) << b;
    EXPECT_GT(reference.solidDistance(x), 0.0) << b;
    EXPECT_GE(interpolateNodes(fields.solidNodeDistance, fields.grid, x), b.radius) << b;
  }
}

TEST(BubbleModel, BirthTimesAreSpreadUniformlyInsideTheSteps) {
  // Claim: birth times are continuous, not quantised to steps: the fractional position
  // (birth − t)/dt of each bubble inside its step, over steps of four lengths, is uniform on
  // (0, 1]. Reference: the uniform distribution, by the Kolmogorov–Smirnov statistic
  // D = sup|F_n − F|. Tolerance: D < 1.949/√n, the 0.1 % critical value (a correct sampler
  // exceeds it with probability 0.001; quantised births would give D ≥ 0.5). Also every fraction
  // is in (0, 1] and no two are equal.
  JetRunOptions o;
  o.jet.speed = 1.5;
  o.steps = {1.0 / 600, 1.0 / 450, 1.0 / 900, 1.0 / 700};
  o.duration = 0.2;
  const JetRun run = runJet(o);
  std::vector<double> fractions;
  std::size_t next = 0;
  for (std::size_t s = 0; s < run.reports.size(); ++s)
    for (std::size_t c = 0; c < run.reports[s].spawn.created; ++c, ++next)
      fractions.push_back((run.bubbles[next].birth - run.stepStart[s]) / run.stepLength[s]);
  ASSERT_EQ(next, run.bubbles.size());
  const std::size_t n = fractions.size();
  ASSERT_GT(n, 500u);
  std::sort(fractions.begin(), fractions.end());
  double d = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    d = std::max({d, (i + 1.0) / n - fractions[i], fractions[i] - static_cast<double>(i) / n});
  const double critical = 1.949 / std::sqrt(static_cast<double>(n));
  std::cout << "[ measured ] " << n << " births: KS D = " << d << " (0.1 % critical value " << critical << ")\n";
  EXPECT_LT(d, critical);
  EXPECT_GT(fractions.front(), 0.0);
  EXPECT_LE(fractions.back(), 1.0);
  EXPECT_EQ(std::set<double>(fractions.begin(), fractions.end()).size(), n);
}

TEST(BubbleModel, BubbleInStillWaterEndsAtTheSurfaceWhenItsTerminalSpeedPredicts) {
  // Claim: a bubble released 5 cm below the surface of still water rises and is ended at the
  // surface at birth + (d₀ − r)/U_T, r = 0.5, 1, 2 mm. Reference: U_T = terminalRiseSpeed
  // (Tomiyama contaminated drag, bubble_rise.h). Tolerance: 10 % (the brief's); the expected
  // deviation is the start-up lag, about U_T·τ with τ ≤ 7 ms the drag relaxation time, ≈ 3 %.
  // Also: its per-frame depths fall and stay above its radius.
  SyntheticTank tank(kCells, kCell, kSurface, kSeed);
  BubbleModel model(BubbleSettings{}, kSeed, kGravity);
  const double radii[] = {0.5e-3, 1e-3, 2e-3};
  const double startDepth = 0.05;
  for (int b = 0; b < 3; ++b)
    ASSERT_TRUE(model.insertBubble(radii[b], {0.03 + 0.03 * b, kSurface - startDepth, 0.06}, 0.0, tank.state()));
  const double dt = 1.0 / 300;
  double t = 0.0;
  for (int n = 0; n < 450 && model.aliveCount() > 0; ++n, t += dt) {
    model.step(tank.state(), t, dt);
    if ((n + 1) % 10 == 0) model.sampleFrame(t + dt);
  }
  ASSERT_EQ(model.bubbles().size(), 3u);
  for (int b = 0; b < 3; ++b) {
    const BubbleHistory& h = model.bubbles()[b];
    const double terminal = terminalRiseSpeed(radii[b], 9.81);
    const double predicted = (startDepth - radii[b]) / terminal;
    ASSERT_TRUE(h.death.has_value()) << h;
    const double lived = *h.death - h.birth;
    std::cout << "[ measured ] r " << radii[b] * 1e3 << " mm: U_T " << terminal << " m/s, ended after " << lived
              << " s, predicted " << predicted << " s (" << 100.0 * (lived / predicted - 1.0) << " %)\n";
    EXPECT_NEAR(lived, predicted, 0.10 * predicted) << h;
    for (std::size_t s = 1; s < h.samples.size(); ++s) {
      EXPECT_LT(h.samples[s].depth, h.samples[s - 1].depth) << "sample " << s << " of " << h;
      EXPECT_GT(h.samples[s].time, h.samples[s - 1].time) << "sample " << s << " of " << h;
    }
    EXPECT_GT(h.samples.back().depth, h.radius) << h;
    EXPECT_LT(h.samples.back().time, *h.death) << h;
    EXPECT_GT(h.samples.size(), 5u) << h;
  }
}

TEST(BubbleModel, SameBubblesBitForBitOnOneAndTwoThreadsAndInAnyParticleOrder) {
  // Claim: the same inputs and seed give bit-identical bubbles (radius, birth, every sample, death)
  // and step reports on 1 and 2 threads, and when the particle arrays are reversed before every
  // step. Reference: the single-threaded run. Tolerance: exact equality (operator== on doubles).
  // The grid's jet (0.1 m/s) is slower than most bubbles rise, so bubbles are carried, accelerated
  // at its edges, and end at the surface: every part of the step is compared.
  JetRunOptions o;
  o.jet.speed = 2.0;
  o.gridJetSpeed = 0.1;
  o.steps = {1.0 / 600, 1.0 / 450};
  o.duration = 0.15;
  JetRun one, two, reversed;
  {
    const oneapi::tbb::global_control limit(oneapi::tbb::global_control::max_allowed_parallelism, 1);
    one = runJet(o);
  }
  {
    const oneapi::tbb::global_control limit(oneapi::tbb::global_control::max_allowed_parallelism, 2);
    two = runJet(o);
    o.reverseEachStep = true;
    reversed = runJet(o);
  }
  printTotals("1 thread", one);
  ASSERT_GT(one.bubbles.size(), 100u);
  std::size_t ended = 0;
  for (const BubbleHistory& b : one.bubbles) ended += b.death.has_value();
  std::cout << "[ measured ] " << one.bubbles.size() << " bubbles, " << ended << " ended\n";
  EXPECT_GT(ended, 0u) << "no bubble ended: the end tests would go unchecked";
  EXPECT_TRUE(one.bubbles == two.bubbles);
  EXPECT_TRUE(one.reports == two.reports);
  EXPECT_TRUE(one.bubbles == reversed.bubbles);
  EXPECT_TRUE(one.reports == reversed.reports);
}

TEST(BubbleModel, InvalidSettingsNameTheirField) {
  // Claim: each invalid setting is refused with std::invalid_argument naming the field.
  // Reference: bubble_settings.h. Tolerance: none (message content).
  struct Case {
    const char* field;
    std::function<void(BubbleSettings&)> spoil;
  };
  const Case cases[] = {
      {"rate", [](BubbleSettings& s) { s.rate = -1.0; }},
      {"minRadius", [](BubbleSettings& s) { s.sizes = PowerLawBubbleSizes{5e-3, 1e-3, 1e-3}; }},
      {"minRadius", [](BubbleSettings& s) { s.sizes = GaussianBubbleSizes{1e-3, 1e-4, 4e-3, 2e-3}; }},
      {"meanRadius", [](BubbleSettings& s) { s.sizes = GaussianBubbleSizes{}; }},
      {"bandCells", [](BubbleSettings& s) { s.bandCells = 0.0; }},
      {"entrainmentDepthCells", [](BubbleSettings& s) { s.entrainmentDepthCells = -2.0; }},
      {"entrainmentWindow", [](BubbleSettings& s) { s.entrainmentWindow = std::nan(""); }},
      {"entrainmentSpeed", [](BubbleSettings& s) { s.entrainmentSpeed = 0.0; }},
      {"probeCells", [](BubbleSettings& s) { s.probeCells = -1.0; }},
      {"seedLifetime", [](BubbleSettings& s) { s.seedLifetime = 0.0; }},
      {"potentialDecayTime", [](BubbleSettings& s) { s.potentialDecayTime = -0.03; }},
      {"jitterCells", [](BubbleSettings& s) { s.jitterCells = -0.5; }},
      {"minSeeds", [](BubbleSettings& s) { s.minSeeds = 0; }},
      {"neighbourhoodCells", [](BubbleSettings& s) { s.neighbourhoodCells = s.neighbourhoodRadii = 0.0; }},
      {"neighbourhoodRadii", [](BubbleSettings& s) { s.neighbourhoodRadii = -4.0; }},
      {"liquidViscosity", [](BubbleSettings& s) { s.rise.liquidViscosity = -1.0; }},
  };
  for (const Case& c : cases) {
    BubbleSettings settings;
    c.spoil(settings);
    try {
      BubbleModel model(settings, kSeed, kGravity);
      ADD_FAILURE() << "accepted a bad " << c.field;
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("BubbleSettings."), std::string::npos) << message;
      EXPECT_NE(message.find(c.field), std::string::npos) << "expected " << c.field << " in: " << message;
    }
  }
  // Valid extremes are accepted: the speed test and the potential decay switched off.
  BubbleSettings off;
  off.entrainmentSpeed = off.potentialDecayTime = std::numeric_limits<double>::infinity();
  off.rate = 0.0;
  EXPECT_NO_THROW(BubbleModel(off, kSeed, kGravity));
}

TEST(BubbleModel, RejectsStepsThatDoNotFollowEachOtherAndMismatchedArrays) {
  // Claim: integration mistakes fail loudly: dt ≤ 0, a step that does not start where the last
  // ended, a frame sampled at another time than the last step's end, ids missing.
  SyntheticTank tank(8, 0.01, 0.05, kSeed);
  BubbleModel model(BubbleSettings{}, kSeed, kGravity);
  EXPECT_THROW(model.step(tank.state(), 0.0, 0.0), std::invalid_argument);
  model.step(tank.state(), 0.0, 0.01);
  EXPECT_THROW(model.step(tank.state(), 0.02, 0.01), std::invalid_argument);
  EXPECT_THROW(model.sampleFrame(0.02), std::invalid_argument);
  EXPECT_NO_THROW(model.sampleFrame(0.01));
  tank.ids().pop_back();
  try {
    model.step(tank.state(), 0.01, 0.01);
    ADD_FAILURE() << "accepted one id fewer than particles";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("particleIds"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fluidsound::sim
