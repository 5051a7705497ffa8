// tests/acoustics/transfer/wave_air_field_test.cpp — the geometric transfer's air side with the
// geometry in place (wave_air_field.h): merging cells keeps thin walls, the ground plane is found
// where the grid's sides agree, a glass of air read through the field resonates at its quarter
// wave, and over an open flat surface the stage gives what the rigid-surface air side gives
// (issue 20; shared transfer.md §3–4).
#include "acoustics/transfer/wave_air_field.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "acoustics/transfer/geometric_transfer.h"
#include "tests/support/water_grid_shapes.h"

namespace fluidsound::acoustics {
namespace {

constexpr double kPi = std::numbers::pi;

/// 4 × 2 × 2 cells of air at 5 mm, every face open.
WaterGrid openAir() {
  WaterGrid g;
  g.cells = {4, 2, 2};
  g.cellSize = 0.005;
  g.phi.assign(g.cellCount(), 1.0f);
  for (int a = 0; a < 3; ++a) {
    std::array<int, 3> f = g.cells;
    ++f[a];
    g.faceOpen[a].assign(static_cast<std::size_t>(f[0]) * f[1] * f[2], 1.0f);
  }
  return g;
}

// Claim: a wall of closed faces through the middle of a merged cell still separates it from its
// neighbour: the merged cell it crosses is shut (every face closed, else it would join air from
// both sides of the wall), and a cell no wall crosses keeps its open faces.
TEST(WaveAirField, MergingKeepsAThinWallInsideAMergedCell) {
  WaterGrid fine = openAir();
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j) fine.faceOpen[0][fine.faceIndex(0, 1, j, k)] = 0.0f;  // x = 5 mm
  const WaterGrid merged = mergedGrid(fine, 2);
  ASSERT_EQ(merged.cells, (std::array<int, 3>{2, 1, 1}));
  EXPECT_EQ(merged.faceOpen[0][merged.faceIndex(0, 1, 0, 0)], 0.0f);
  EXPECT_EQ(merged.faceOpen[1][merged.faceIndex(1, 0, 1, 0)], 0.0f);  // the walled cell's top
  EXPECT_EQ(merged.faceOpen[1][merged.faceIndex(1, 1, 1, 0)], 1.0f);  // its neighbour's top
  EXPECT_EQ(merged.cellSize, 0.01);
  EXPECT_FLOAT_EQ(merged.phi[0], 1.0f);
}

// Claim: the plane is the height where every side column meets open air (a liquid reaching the
// sides); a tube standing inside the grid and the fluid's domain wall on top do not change it, a
// wall on one side does.
TEST(WaveAirField, TheGroundPlaneIsWhereEverySideColumnMeetsOpenAir) {
  WaterGrid tube = test::tubeOnLiquid(0.035, 0.06, 0.01);
  for (int k = 0; k < tube.cells[2]; ++k)  // the fluid's domain wall on top: not a wall for air
    for (int i = 0; i < tube.cells[0]; ++i)
      tube.faceOpen[1][tube.faceIndex(1, i, tube.cells[1], k)] = 0.0f;
  ASSERT_TRUE(groundPlaneHeight(tube).has_value());
  EXPECT_NEAR(*groundPlaneHeight(tube), 0.0, 1e-12);
  WaterGrid walled = tube;
  for (int j = 2; j < 6; ++j)  // close the top faces of a column on the −x side above the liquid
    walled.faceOpen[1][walled.faceIndex(1, 0, j + 1, 3)] = 0.0f;
  EXPECT_FALSE(groundPlaneHeight(walled).has_value());
}

// Reference: c_a/(4(L + 0.6133 r)) (Levine & Schwinger 1948), as for the solver alone
// (air_wave_solve_test.cpp), now through the field a frame builds: the 5 mm grid merged to 1 cm,
// the value carried to the liquid surface, read between frequency bins. The merged wall may sit
// up to half a cell inward, so r is taken between the staircase's equivalent radius and half a
// cell less: 5 % allowed, the tolerance.
TEST(WaveAirField, AGlassOfAirReadThroughTheFieldResonatesAtItsQuarterWave) {
  const AirProperties air;
  const double radius = 0.035, column = 0.08;
  const WaterGrid fine = test::tubeOnLiquid(radius, column, 0.005);
  WaveAirOptions options;
  options.ringTime = 0.04;
  const WaveAirField field(fine, {0.0025, 0.4, 0.0025}, air, options);
  EXPECT_NEAR(field.maxFrequency(), air.soundSpeed / 0.06, 1e-9);
  const double expected = air.soundSpeed / (4.0 * (column + 0.6133 * (radius - 0.0025)));
  double best = 0.0, peak = 0.0;
  for (double hz = 0.5 * expected; hz < 1.5 * expected; hz += 2.0) {
    const auto p = field.at({0.0025, 0.0, 0.0025}, 2.0 * kPi * hz);
    ASSERT_TRUE(p.has_value()) << hz;
    if (std::abs(*p) > best) best = std::abs(*p), peak = hz;
  }
  EXPECT_NEAR(peak / expected, 1.0, 0.05) << peak << " Hz";
  EXPECT_FALSE(field.at({0.0025, 0.0, 0.0025}, 2.0 * kPi * (field.maxFrequency() + 10.0)));
  EXPECT_FALSE(field.at({0.0025, 0.1, 0.0025}, 2.0 * kPi * expected));  // far above the liquid
}

// Reference: the glass of air above, its strongest resonance as resonances() finds it from the
// probes' largest gain: at the quarter wave within 5 % (the tolerance), and decaying at the open
// end's radiation rate. An unflanged pipe's open end reflects |R| = e^{−(ka)²/2} at low ka
// (Levine & Schwinger 1948), so a quarter-wave column's amplitude falls by |R| per round trip
// 2L'/c: β_r = c(ka)²/(4L'), L' = L + 0.6133a. That is for a pipe in free space; ours has a
// staircase wall, the merged grid, 8 Hz bins across a peak some 60 Hz wide and the ground plane
// 8 cm below its open end: 30 % allowed (measured: 836 Hz against 859, −2.7 %; 170 /s against
// 224, −24 %).
TEST(WaveAirField, AGlassOfAirRingsAtItsQuarterWaveAndDecaysAsItsOpenEndRadiates) {
  const AirProperties air;
  const double radius = 0.035, column = 0.08;
  WaveAirOptions options;
  options.ringTime = 0.04;
  const WaveAirField field(test::tubeOnLiquid(radius, column, 0.005), {0.0025, 0.4, 0.0025}, air, options);
  const std::vector<AirResonance> found = field.resonances();
  ASSERT_FALSE(found.empty());
  const AirResonance* resonance = &found.front();
  const double a = radius - 0.0025, length = column + 0.6133 * a;
  const double expected = air.soundSpeed / (4.0 * length);
  const double ka = 2.0 * kPi * expected / air.soundSpeed * a;
  const double radiating = air.soundSpeed * ka * ka / (4.0 * length);
  std::printf("glass resonance %.0f Hz (quarter wave %.0f), gain %.1f, decay %.0f /s (radiation %.0f /s)\n",
              resonance->frequency, expected, resonance->gain, resonance->decayRate, radiating);
  EXPECT_NEAR(resonance->frequency / expected, 1.0, 0.05);
  EXPECT_GT(resonance->gain, kMinResonanceGain);
  EXPECT_NEAR(resonance->decayRate / radiating, 1.0, 0.30);
  // Without the glass, open water has no resonance to find.
  EXPECT_TRUE(WaveAirField(test::waterBox({0.1, 0.07, 0.02, 0.005, 2}), {0.05, 1.07, 0.01}, air, options)
                   .resonances()
                   .empty());
}

// Reference: the rigid-surface air side, the free field doubled by the surface (shared
// transfer.md §1), which is exact over an open flat surface with nothing in the way; the wave air
// side must reproduce it end to end there within 3 % (the tolerance), so the geometric
// model's E(θ) tests hold for it too. A 10 × 7 × 2 cm box of water filled to the grid's sides at
// 5 mm, the air at 1 cm, bubbles 1–5 kHz 2 cm deep, listeners overhead and at 60°. The values are
// bit-identical for 1 and 2 threads.
TEST(WaveAirField, OverAnOpenFlatSurfaceTheStageHearsTheRigidSurfacesDoubling) {
  const WaterGrid box = test::waterBox({0.1, 0.07, 0.02, 0.005, 2});
  TransferSetup setup;
  setup.listeners = {{"above", {0.05, 1.07, 0.01}}, {"aside", {0.9, 0.56, 0.01}}};
  BubbleTrackSet tracks;
  tracks.listeners = {"above", "aside"};
  for (const double radius : {3e-3, 1.5e-3, 1e-3, 0.7e-3}) {
    BubbleTrack bubble;
    bubble.radius = radius;
    TrackSample s;
    s.depth = 0.02;
    s.position = Vec3{0.052, 0.05, 0.01};
    bubble.track.push_back(s);
    tracks.bubbles.push_back(bubble);
  }
  StageObserver observer;  // no progress, never stops
  const TransferResult rigid = computeGeometricTransfer(tracks, test::SameGridEveryFrame(box), setup, {}, observer);
  GeometricTransferOptions wave;
  wave.waveAir = WaveAirOptions{};
  TransferResult one, two;
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
    one = computeGeometricTransfer(tracks, test::SameGridEveryFrame(box), setup, wave, observer);
  }
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
    two = computeGeometricTransfer(tracks, test::SameGridEveryFrame(box), setup, wave, observer);
  }
  EXPECT_EQ(one.tracks, two.tracks);
  EXPECT_EQ(one.geometric.airSolves, 2u);
  EXPECT_EQ(one.geometric.airSamples, 4u);
  for (std::size_t b = 0; b < tracks.bubbles.size(); ++b)
    for (std::size_t l = 0; l < 2; ++l) {
      const double w = one.tracks.bubbles[b].track[0].transfer[l];
      const double r = rigid.tracks.bubbles[b].track[0].transfer[l];
      EXPECT_NEAR(w / r, 1.0, 0.03) << "bubble " << b << " listener " << l;
    }
}

}  // namespace
}  // namespace fluidsound::acoustics
