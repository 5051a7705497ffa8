// tests/acoustics/transfer/transfer_stage_test.cpp — acoustics::computeTransfer with fake frames (a plane
// the same for every frame): the values are the image-source model's under that plane, a tilted
// plane never puts an air listener under water, ω comes from the setup's oscillator model, errors
// name their field, the first failing frame's error wins, and the observer sees every chunk.
#include "acoustics/transfer/transfer_stage.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include "acoustics/bubble/minnaert.h"

namespace fluidsound::acoustics {
namespace {

/// The plane through centre + depth·normal with the given unit normal.
LocalSurface planeAbove(const Vec3& centre, double depth, const Vec3& normal) {
  LocalSurface s{centre, normal, depth};
  for (int a = 0; a < 3; ++a) s.point[a] += depth * normal[a];
  return s;
}

class PlaneSurface : public FrameSurface {
 public:
  explicit PlaneSurface(Vec3 normal) : normal_(normal) {}
  LocalSurface surfaceAbove(const Vec3& centre, double depth, const Vec3&) const override {
    return planeAbove(centre, depth, normal_);
  }

 private:
  Vec3 normal_;
};

/// Every frame's surface is a plane with `normal` right above each bubble; counts the frames opened.
class PlaneFrames : public FrameSurfaces {
 public:
  explicit PlaneFrames(Vec3 normal = {0.0, 1.0, 0.0}) : normal_(normal) {}
  std::unique_ptr<FrameSurface> open(int) const override {
    ++opened;
    return std::make_unique<PlaneSurface>(normal_);
  }
  mutable std::atomic<int> opened{0};

 private:
  Vec3 normal_;
};

/// Records what the stage reported; optionally asks it to stop at the n-th question (1-based).
class RecordingObserver : public StageObserver {
 public:
  void started(double totalUnits) override { total = totalUnits; }
  void progress(double fraction) override { fractions.push_back(fraction); }
  bool wasInterrupted() override { return ++questions == stopAt; }
  double total = -1.0;
  std::vector<double> fractions;
  int questions = 0;
  int stopAt = 0;
};

TrackSample sampleAt(double time, double depth, Vec3 position) {
  TrackSample s;
  s.time = time;
  s.depth = depth;
  s.position = position;
  return s;
}

/// `bubbles` bubbles of 1 mm, each with one sample per frame in `frames` frames at 30 fps.
BubbleTrackSet tracksOver(int bubbles, int frames) {
  BubbleTrackSet tracks;
  tracks.listeners = {"air", "water"};
  for (int b = 0; b < bubbles; ++b) {
    BubbleTrack bubble;
    bubble.radius = 1e-3 * (1.0 + 0.5 * b);
    for (int f = 0; f < frames; ++f)
      bubble.track.push_back(sampleAt(f / 30.0, 0.01 + 0.002 * b, {0.1 * b, -0.01, 0.02 * f}));
    tracks.bubbles.push_back(bubble);
  }
  return tracks;
}

TransferSetup setupWith(std::vector<TransferListener> listeners) {
  TransferSetup setup;
  setup.listeners = std::move(listeners);
  setup.fps = 30.0;
  setup.lastFrame = 60;
  return setup;
}

const std::vector<TransferListener> kAirAndWater = {{"air", {0.3, 0.5, 0.1}}, {"water", {-0.2, -0.3, 0.4}}};

double adiabaticOmega(const BubbleTrack& bubble, const TransferSetup& setup) {
  return naturalAngularFrequency(bubble.radius, setup.liquid.ambientPressure, setup.liquid, setup.model);
}

// Claim: under a flat horizontal surface every sample's value is imageSourceTransferAmplitude
// under the plane its frame gives, with the bubble's natural ω under the default model (what the
// stage computed before it was a library function); each frame with samples is opened once, and
// the stats count bubbles, samples and frames. Reference: the model's function, called directly.
TEST(TransferStage, FlatSurfaceGivesTheImageSourceValues) {
  const PlaneFrames frames;
  const TransferSetup setup = setupWith(kAirAndWater);
  StageObserver quiet;
  const TransferResult result = computeTransfer(tracksOver(3, 5), frames, setup, quiet);
  ASSERT_EQ(result.tracks.bubbles.size(), 3u);
  EXPECT_EQ(result.bubbles, 3u);
  EXPECT_EQ(result.samples, 15u);
  EXPECT_EQ(result.framesRead, 5u);
  EXPECT_EQ(frames.opened.load(), 5);
  for (const BubbleTrack& bubble : result.tracks.bubbles)
    for (const TrackSample& s : bubble.track) {
      ASSERT_EQ(s.transfer.size(), 2u);
      const LocalSurface plane = planeAbove(*s.position, s.depth, setup.up);
      for (std::size_t l = 0; l < 2; ++l)
        EXPECT_EQ(s.transfer[l], imageSourceTransferAmplitude(*s.position, plane, kAirAndWater[l].position,
                                                              adiabaticOmega(bubble, setup), setup.liquid, setup.air));
    }
}

// Claim: a tilted local plane (normal 60° from up) that would put an air listener (above the level
// plane at the track's depth) under water is replaced by the level plane for that listener only;
// a listener above both planes, and one under water, keep the tilted plane.
TEST(TransferStage, TiltedPlaneDoesNotHideAnAirListener) {
  const double s60 = std::sin(std::numbers::pi / 3.0), c60 = std::cos(std::numbers::pi / 3.0);
  const Vec3 tilted{s60, c60, 0.0};
  const PlaneFrames frames(tilted);
  const std::vector<TransferListener> listeners = {
      {"hidden", {-1.0, 0.1, 0.0}}, {"seen", {1.0, 0.1, 0.0}}, {"water", {0.0, -0.5, 0.0}}};
  const TransferSetup setup = setupWith(listeners);
  BubbleTrackSet tracks;
  BubbleTrack bubble;
  bubble.radius = 1e-3;
  const Vec3 centre{0.0, 0.0, 0.0};
  bubble.track = {sampleAt(0.0, 0.01, centre)};
  tracks.bubbles = {bubble};
  StageObserver quiet;
  const std::vector<double> t = computeTransfer(tracks, frames, setup, quiet).tracks.bubbles[0].track[0].transfer;
  ASSERT_EQ(t.size(), 3u);
  const double omega = adiabaticOmega(bubble, setup);
  const auto value = [&](const LocalSurface& plane, std::size_t l) {
    return imageSourceTransferAmplitude(centre, plane, listeners[l].position, omega, setup.liquid, setup.air);
  };
  const LocalSurface level = planeAbove(centre, 0.01, setup.up), local = planeAbove(centre, 0.01, tilted);
  ASSERT_NE(value(level, 0), value(local, 0)) << "the geometry must make the rule matter";
  EXPECT_EQ(t[0], value(level, 0));
  EXPECT_EQ(t[1], value(local, 1));
  EXPECT_EQ(t[2], value(local, 2));
}

// Claim: ω comes from setup.model — the thermal polytropic index changes a water listener's value
// (which depends on k_w h) to the model function's value with the thermal ω.
TEST(TransferStage, OscillatorModelGivesOmega) {
  const PlaneFrames frames;
  TransferSetup setup = setupWith(kAirAndWater);
  setup.model.polytropic = PolytropicModel::Thermal;
  StageObserver quiet;
  const BubbleTrackSet tracks = tracksOver(1, 1);
  const TransferResult thermal = computeTransfer(tracks, frames, setup, quiet);
  const TrackSample& s = thermal.tracks.bubbles[0].track[0];
  const double omega =
      naturalAngularFrequency(tracks.bubbles[0].radius, setup.liquid.ambientPressure, setup.liquid, setup.model);
  ASSERT_NE(omega, adiabaticOmega(tracks.bubbles[0], setupWith(kAirAndWater)));
  const LocalSurface plane = planeAbove(*s.position, s.depth, setup.up);
  EXPECT_EQ(s.transfer[1], imageSourceTransferAmplitude(*s.position, plane, kAirAndWater[1].position, omega,
                                                        setup.liquid, setup.air));
  const TransferResult adiabatic = computeTransfer(tracks, frames, setupWith(kAirAndWater), quiet);
  EXPECT_NE(s.transfer[1], adiabatic.tracks.bubbles[0].track[0].transfer[1]);
}

// Bad input: a sample with no position names its bubble and sample, as the tracks' field.
TEST(TransferStage, SampleWithoutPositionNamesItsField) {
  const PlaneFrames frames;
  BubbleTrackSet tracks = tracksOver(2, 3);
  tracks.bubbles[1].track[2].position.reset();
  StageObserver quiet;
  try {
    computeTransfer(tracks, frames, setupWith(kAirAndWater), quiet);
    FAIL() << "no error";
  } catch (const TransferInputError& e) {
    EXPECT_EQ(e.input(), TransferInput::Tracks);
    EXPECT_EQ(e.field(), "bubbles[1].track[2]");
    EXPECT_EQ(e.expected(), "a position (written by fluidsound simulate)");
    EXPECT_EQ(e.found(), "none");
  }
}

// Bad input: a listener at a bubble's surface point (r = 0 in air) names the listener, as the
// scene's field, with the model's reason as what was found.
TEST(TransferStage, ListenerAtASurfacePointNamesItsField) {
  const PlaneFrames frames;
  BubbleTrackSet tracks = tracksOver(1, 1);
  const TrackSample& s = tracks.bubbles[0].track[0];
  const Vec3 surfacePoint{(*s.position)[0], (*s.position)[1] + s.depth, (*s.position)[2]};
  StageObserver quiet;
  try {
    computeTransfer(tracks, frames, setupWith({kAirAndWater[0], {"on it", surfacePoint}}), quiet);
    FAIL() << "no error";
  } catch (const TransferInputError& e) {
    EXPECT_EQ(e.input(), TransferInput::Listeners);
    EXPECT_EQ(e.field(), "listeners[1].position");
    EXPECT_EQ(e.expected(), "a listener away from every bubble and its surface point");
    EXPECT_FALSE(e.found().empty());
  }
}

// Claim: of several failing frames, in one chunk or in different chunks, the first in frame order
// fails the stage, whatever the thread count (frame 2's bubble 0, not frames 5 or 20).
TEST(TransferStage, FirstFailingFrameInFrameOrderWins) {
  const PlaneFrames frames;
  BubbleTrackSet tracks = tracksOver(2, 24);
  tracks.bubbles[1].track[20].position.reset();
  tracks.bubbles[1].track[5].position.reset();
  tracks.bubbles[0].track[2].position.reset();
  for (int threads : {1, 3}) {
    tbb::task_arena arena(threads);
    arena.execute([&] {
      StageObserver quiet;
      try {
        computeTransfer(tracks, frames, setupWith(kAirAndWater), quiet);
        ADD_FAILURE() << "no error";
      } catch (const TransferInputError& e) {
        EXPECT_EQ(e.field(), "bubbles[0].track[2]") << threads << " threads";
      }
    });
  }
}

// Claim: the result is the same, value for value, with 1 and 3 threads.
TEST(TransferStage, ResultDoesNotDependOnTheThreadCount) {
  const PlaneFrames frames;
  std::vector<BubbleTrackSet> results;
  for (int threads : {1, 3}) {
    tbb::task_arena arena(threads);
    arena.execute([&] {
      StageObserver quiet;
      results.push_back(computeTransfer(tracksOver(4, 30), frames, setupWith(kAirAndWater), quiet).tracks);
    });
  }
  EXPECT_TRUE(results[0] == results[1]);
}

// Claim: the observer learns the number of frames, is asked before each chunk of
// kTransferFramesPerChunk frames and told the fraction after it; asking to stop ends the stage
// with StageInterrupted naming the chunk's first frame, before that chunk's frames are opened.
TEST(TransferStage, ObserverSeesEveryChunkAndCanStopTheStage) {
  const PlaneFrames frames;
  RecordingObserver observer;
  computeTransfer(tracksOver(1, 20), frames, setupWith(kAirAndWater), observer);
  EXPECT_EQ(observer.total, 20.0);
  EXPECT_EQ(observer.questions, 3);
  EXPECT_EQ(observer.fractions, (std::vector<double>{8.0 / 20.0, 16.0 / 20.0, 1.0}));

  const PlaneFrames stopped;
  RecordingObserver stopping;
  stopping.stopAt = 2;
  try {
    computeTransfer(tracksOver(1, 20), stopped, setupWith(kAirAndWater), stopping);
    ADD_FAILURE() << "the stage did not stop";
  } catch (const StageInterrupted& e) {
    EXPECT_STREQ(e.what(), "transfer frame 8");
  }
  EXPECT_EQ(stopped.opened.load(), static_cast<int>(kTransferFramesPerChunk));
  EXPECT_EQ(stopping.fractions.size(), 1u);
}

}  // namespace
}  // namespace fluidsound::acoustics
