// tests/acoustics/transfer/geometric_transfer_test.cpp — the geometric model as a stage: its two
// routes agree, band interpolation holds its tolerance, the values are finite, non-negative and
// thread-count independent, and bad options or a failing solve are errors naming the field or
// the frame (issue 19; shared transfer.md §1–2).
#include "acoustics/transfer/geometric_transfer.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <limits>

#include "acoustics/bubble/instantaneous_frequency.h"
#include "acoustics/bubble/minnaert.h"
#include "acoustics/transfer/rigid_surface_air_field.h"
#include "acoustics/transfer/water_helmholtz.h"
#include "acoustics/transfer/water_modes.h"
#include "tests/support/water_grid_shapes.h"

namespace fluidsound::acoustics {
namespace {

/// The frames of these tests: every one the same 10 × 7 × 2 cm box of water at 5 mm cells,
/// surface at y = 7 cm.
WaterGrid box() { return test::waterBox({0.1, 0.07, 0.02, 0.005, 2}); }

TransferSetup setupWithTwoListeners() {
  TransferSetup setup;
  setup.listeners = {{"above", {0.05, 0.6, 0.01}}, {"aside", {0.6, 0.3, 0.01}}};
  setup.fps = 30.0;
  setup.lastFrame = 10;
  return setup;
}

/// One bubble per radius, each with one sample in frame 0 at a depth of 2 cm.
BubbleTrackSet bubblesOfRadii(const std::vector<double>& radii) {
  BubbleTrackSet tracks;
  tracks.listeners = {"above", "aside"};
  for (std::size_t b = 0; b < radii.size(); ++b) {
    BubbleTrack bubble;
    bubble.radius = radii[b];
    TrackSample s;
    s.depth = 0.02;
    s.position = Vec3{0.03 + 0.004 * static_cast<double>(b % 10), 0.05, 0.01};
    bubble.track.push_back(s);
    tracks.bubbles.push_back(bubble);
  }
  return tracks;
}

TransferResult run(const BubbleTrackSet& tracks, const GeometricTransferOptions& options = {}) {
  StageObserver observer;  // no progress, never stops
  return computeGeometricTransfer(tracks, test::SameGridEveryFrame(box()), setupWithTwoListeners(), options,
                                  observer);
}

// Reference: reciprocity (shared transfer.md §1) — the adjoint route and the reciprocal route
// solve transposed systems of one complex-symmetric matrix, so at the same frequency they agree
// to rounding. Many samples at one radius take the reciprocal route (one band); one sample alone
// takes the adjoint route. Tolerance 1e-9 relative: LU back-substitution rounding.
TEST(GeometricTransfer, ReciprocalAndAdjointRoutesAgreeAtTheSameFrequency) {
  const TransferResult many = run(bubblesOfRadii(std::vector<double>(12, 1.5e-3)));
  ASSERT_EQ(many.geometric.reciprocalFrames, 1u);
  ASSERT_EQ(many.geometric.adjointFrames, 0u);
  for (std::size_t b = 0; b < 12; ++b) {
    BubbleTrackSet one = bubblesOfRadii(std::vector<double>(12, 1.5e-3));
    one.bubbles = {one.bubbles[b]};
    const TransferResult alone = run(one);
    ASSERT_EQ(alone.geometric.adjointFrames, 1u);
    for (int l = 0; l < 2; ++l) {
      const double reciprocal = many.tracks.bubbles[b].track[0].transfer[l];
      const double adjoint = alone.tracks.bubbles[0].track[0].transfer[l];
      EXPECT_NEAR(reciprocal / adjoint, 1.0, 1e-9) << "bubble " << b << " listener " << l;
    }
  }
}

/// The worst |reciprocal / adjoint − 1| over every third bubble and both listeners: the adjoint
/// route solves each sample alone at its own frequency.
double worstAgainstAdjoint(const std::vector<double>& radii, const TransferResult& banded) {
  double worst = 0.0;
  for (std::size_t b = 0; b < radii.size(); b += 3) {
    BubbleTrackSet one = bubblesOfRadii(radii);
    one.bubbles = {one.bubbles[b]};
    const TransferResult exact = run(one);
    EXPECT_EQ(exact.geometric.adjointFrames, 1u);
    for (int l = 0; l < 2; ++l)
      worst = std::max(worst, std::abs(banded.tracks.bubbles[b].track[0].transfer[l] /
                                           exact.tracks.bubbles[0].track[0].transfer[l] -
                                       1.0));
  }
  return worst;
}

// Reference: the adjoint route at each sample's own frequency. The reciprocal route reads
// between Chebyshev bands, ⌈1.5τ⌉ + 12 of them, which interpolate the air phase and the water's
// non-resonant remainder to 1e-7 (chebyshev_bands_test.cpp; docs/transfer.md, "Bands and
// routes"). Tolerance 1e-6.
TEST(GeometricTransfer, BandInterpolationHoldsTheBandRulesTolerance) {
  std::vector<double> radii;
  for (int b = 0; b < 40; ++b) radii.push_back(1.0e-3 + 5.0e-5 * b);  // ≈ 3.3 … 1.1 kHz
  const TransferResult banded = run(bubblesOfRadii(radii));
  ASSERT_EQ(banded.geometric.reciprocalFrames, 1u);
  ASSERT_GE(banded.geometric.bands, 2u);
  EXPECT_LT(worstAgainstAdjoint(radii, banded), 1e-6);
}

// Reference: as above, across the box's own resonances. The 7 cm deep box rings first at c_w/(4H)
// = 5.3 kHz (shared transfer.md §3), then at its lateral modes; bubbles from 1.1 to 13 kHz span
// several. Those below 1.5 × the top frequency are taken out and added back in closed form at
// each sample's frequency, so the interpolation never crosses a pole. Tolerance 1e-6.
TEST(GeometricTransfer, ResonancesInsideTheBandRangeAreAddedBackExactly) {
  std::vector<double> radii;
  for (int b = 0; b < 48; ++b) radii.push_back(2.5e-4 * std::pow(12.0, b / 47.0));  // ≈ 13 … 1.1 kHz
  const TransferResult banded = run(bubblesOfRadii(radii));
  ASSERT_EQ(banded.geometric.reciprocalFrames, 1u);
  EXPECT_GE(banded.geometric.modes, 3u);
  EXPECT_LT(worstAgainstAdjoint(radii, banded), 1e-6);
}

/// The box's transfer from a sample at `omega` to the first listener, by the adjoint route done
/// here by hand with the whole operator at the loss η + extraLoss (UMFPACK).
double transferAtLoss(const BubbleTrack& bubble, double omega, double extraLoss) {
  const TransferSetup setup = setupWithTwoListeners();
  const WaterHelmholtz water(box(), setup.liquid.soundSpeed, GeometricTransferOptions{}.lossFactor);
  const PointSample sample = water.sampleAt(*bubble.track[0].position);
  const std::vector<Complex> weights = water.airWeights(
      sample, water.factorise(omega, HelmholtzMethod::Reference, extraLoss)->adjoint(sample));
  Complex u(0.0);
  for (std::size_t a = 0; a < weights.size(); ++a)
    u += weights[a] * rigidSurfaceAirPressure(water.airPoints()[a].position,
                                              setup.listeners[0].position, omega, setup.air);
  return transferFromReciprocalPressure(u, omega, setup.liquid);
}

// Reference: a source that rings down, q(t) = e^{(iω − β)t}, drives a linear system H as
// H(iω − β)·q(t) plus the system's own free ring at its poles (residue theorem, Laplace
// transform). The water's resonance λ₁ = k₁², with loss η, answers at the bubble's complex
// frequency with 1/(k²(δ − η)) (δ = 2β/ω, k = k₁), i.e. the loss factor η − δ; the model
// broadens it to η + δ (docs/transfer.md, "Resonances"): equal to 2η/δ ≈ 2.4 % for this bubble
// (δ ≈ 0.046; measured 2.6 %), plus O(δ²) from the modes not broadened — 5 % allowed. The steady
// value at the real frequency, 1/(k²η), is (η + δ)/η ≈ 80× larger; it must be at least 30×.
TEST(GeometricTransfer, ABubbleOnAResonanceIsHeardThroughItsOwnBandwidth) {
  const TransferSetup setup = setupWithTwoListeners();
  const double c = setup.liquid.soundSpeed;
  const WaterHelmholtz water(box(), c, GeometricTransferOptions{}.lossFactor);
  const WaterModes modes = lowestWaterModes(water, std::pow(2.0 * std::numbers::pi * 8000.0 / c, 2), 160);
  const double target = std::sqrt(modes.eigenvalue[0]) * c;  // ≈ 2π · 5.3 kHz
  const double depth = 0.02;
  const double pressure = ambientPressureAt(depth, setup.liquid, setup.model);
  double lo = 2e-4, hi = 2e-3;  // ω falls with R
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (naturalAngularFrequency(mid, pressure, setup.liquid, setup.model) > target ? lo : hi) = mid;
  }
  BubbleTrackSet tracks = bubblesOfRadii({0.5 * (lo + hi)});
  const BubbleTrack& bubble = tracks.bubbles[0];
  const double omega = naturalAngularFrequency(bubble.radius, pressure, setup.liquid, setup.model);
  const double delta = ringingBubble(bubble, setup.liquid, setup.model).deep.dampingConstant;
  ASSERT_GT(delta, 0.03);
  const double model = run(tracks).tracks.bubbles[0].track[0].transfer[0];
  const double forced = transferAtLoss(bubble, omega, -delta);
  const double steady = transferAtLoss(bubble, omega, 0.0);
  EXPECT_NEAR(model / forced, 1.0, 0.05);
  EXPECT_GT(steady / model, 30.0);
}

TEST(GeometricTransfer, ValuesAreFiniteNonNegativeAndTheSameForOneAndTwoThreads) {
  std::vector<double> radii;
  for (int b = 0; b < 30; ++b) radii.push_back(0.5e-3 + 1.0e-4 * b);
  BubbleTrackSet tracks = bubblesOfRadii(radii);
  for (std::size_t b = 0; b < tracks.bubbles.size(); ++b)  // spread the samples over frames
    tracks.bubbles[b].track[0].time = static_cast<double>(b % 9) / 30.0;
  TransferResult one, two;
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
    one = run(tracks);
  }
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
    two = run(tracks);
  }
  EXPECT_EQ(one.tracks, two.tracks);
  EXPECT_EQ(one.geometric.factorisations, two.geometric.factorisations);
  for (const BubbleTrack& b : one.tracks.bubbles)
    for (const double t : b.track[0].transfer) {
      EXPECT_TRUE(std::isfinite(t));
      EXPECT_GE(t, 0.0);
    }
  EXPECT_EQ(one.geometric.samplesOutsideLiquid, 0u);
}

TEST(GeometricTransfer, OptionsOutOfRangeNameTheirField) {
  const BubbleTrackSet tracks = bubblesOfRadii({1e-3});
  const auto fieldOf = [&](const GeometricTransferOptions& o) {
    try {
      run(tracks, o);
    } catch (const TransferInputError& e) {
      EXPECT_EQ(e.input(), TransferInput::Options);
      return e.field();
    }
    return std::string("no error");
  };
  GeometricTransferOptions o;
  o.maxBands = 1;
  EXPECT_EQ(fieldOf(o), "transfer.max_bands");
  o.maxBands = kMaxTransferBands + 1;
  EXPECT_EQ(fieldOf(o), "transfer.max_bands");
  o = {};
  o.lossFactor = 0.0;
  EXPECT_EQ(fieldOf(o), "transfer.loss_factor");
  o.lossFactor = 0.2;
  EXPECT_EQ(fieldOf(o), "transfer.loss_factor");
  o.lossFactor = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(fieldOf(o), "transfer.loss_factor");
  o = {};
  o.maxFrequency = -1.0;
  EXPECT_EQ(fieldOf(o), "transfer.max_frequency");
  o.maxFrequency = kMaxTransferFrequency * 2.0;
  EXPECT_EQ(fieldOf(o), "transfer.max_frequency");
}

// Reference: the image-source model under the level plane (computeTransfer's flat-surface value),
// which a sample above the frequency limit takes instead of the grid's. The grid's own limit at
// 5 mm cells is c_a/(4h) = 17.2 kHz: a 0.15 mm bubble (≈ 21 kHz) is above it, a 1 mm one below.
TEST(GeometricTransfer, SamplesAboveTheFrequencyLimitTakeTheLevelPlaneValue) {
  const TransferResult result = run(bubblesOfRadii({1.5e-4, 1e-3}));
  EXPECT_EQ(result.geometric.samplesAboveLimit, 1u);
  const TrackSample& high = result.tracks.bubbles[0].track[0];
  const TransferSetup setup = setupWithTwoListeners();
  const double omega = naturalAngularFrequency(
      1.5e-4, ambientPressureAt(high.depth, setup.liquid, setup.model), setup.liquid, setup.model);
  LocalSurface level{*high.position, setup.up, high.depth};
  level.point[1] += high.depth;
  for (int l = 0; l < 2; ++l)
    EXPECT_DOUBLE_EQ(high.transfer[l],
                     imageSourceTransferAmplitude(*high.position, level, setup.listeners[l].position,
                                                  omega, setup.liquid, setup.air));
  GeometricTransferOptions wide;
  wide.maxFrequency = 30000.0;
  EXPECT_EQ(run(bubblesOfRadii({1.5e-4, 1e-3}), wide).geometric.samplesAboveLimit, 0u);
}

TEST(GeometricTransfer, AFailingSolveIsAnErrorNamingTheFrame) {
  WaterGrid broken = box();
  broken.faceOpen[1][broken.faceIndex(1, 5, 10, 1)] = std::numeric_limits<float>::quiet_NaN();
  BubbleTrackSet tracks = bubblesOfRadii({1e-3});
  tracks.bubbles[0].track[0].time = 4.0 / 30.0;
  StageObserver observer;  // no progress, never stops
  try {
    computeGeometricTransfer(tracks, test::SameGridEveryFrame(broken), setupWithTwoListeners(), {}, observer);
    ADD_FAILURE() << "no error";
  } catch (const TransferSolveError& e) {
    EXPECT_EQ(e.frame(), 4);
    EXPECT_NE(std::string(e.what()).find("transfer frame 4"), std::string::npos) << e.what();
  }
}

TEST(GeometricTransfer, AListenerInTheLiquidIsAnInputError) {
  BubbleTrackSet tracks = bubblesOfRadii({1e-3});
  TransferSetup setup = setupWithTwoListeners();
  setup.listeners[1].position = {0.05, 0.03, 0.01};
  StageObserver observer;  // no progress, never stops
  try {
    computeGeometricTransfer(tracks, test::SameGridEveryFrame(box()), setup, {}, observer);
    ADD_FAILURE() << "no error";
  } catch (const TransferInputError& e) {
    EXPECT_EQ(e.field(), "listeners[1].position");
  }
}

}  // namespace
}  // namespace fluidsound::acoustics

namespace fluidsound::acoustics {
namespace {

// Reference: the complex LU of K(ω) itself (HelmholtzMethod::Reference). The fast method's real
// LDLᵀ with refinement stops at a relative residual of kRefinementTolerance, so the two agree to
// ~1e-12 times the condition; tolerance 1e-8. Frequencies: below, at (within the loss of) and
// above the box's first resonance c_w/(4H) = 5.29 kHz, where the fast method falls back to the LU.
TEST(WaterHelmholtzMethods, FastAndReferenceFactorisationsAgree) {
  const WaterHelmholtz water(box(), 1482.0, 5.59e-4);
  const PointSample sample = water.sampleAt({0.05, 0.05, 0.01});
  ASSERT_FALSE(sample.cells.empty());
  for (const double hertz : {800.0, 1482.0 / (4.0 * 0.07), 7000.0, 15000.0}) {
    const double omega = 2.0 * 3.141592653589793 * hertz;
    const Eigen::VectorXcd fast = water.factorise(omega, HelmholtzMethod::Fast)->adjoint(sample);
    const Eigen::VectorXcd exact =
        water.factorise(omega, HelmholtzMethod::Reference)->adjoint(sample);
    EXPECT_LT((fast - exact).norm() / exact.norm(), 1e-8) << hertz << " Hz";
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
