// Tests of acoustics/synthesis/synthesis_stage.h: the stage renders exactly what the Synthesizer
// renders for the same tracks and settings, resolves its settings from the options and the tracks,
// and reports progress and stops through its StageObserver.
#include "acoustics/synthesis/synthesis_stage.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace fluidsound::acoustics {
namespace {

/// Two listeners, bubbles of several sizes born over `seconds`, each rising through a short track
/// whose transfer differs per listener.
BubbleTrackSet bubblesOver(double seconds) {
  BubbleTrackSet set;
  set.listeners = {"left", "right"};
  set.sampleRate = 44100.0;
  for (int i = 0; i < 40; ++i) {
    BubbleTrack b;
    b.radius = 0.0008 + 0.0001 * (i % 13);
    b.birth = seconds * i / 40.0;
    for (int k = 0; k < 4; ++k)
      b.track.push_back(
          {b.birth + k / 30.0, 0.02 - 0.004 * k, {0.6 + 0.05 * k, 0.9 - 0.1 * k}, {}});
    set.bubbles.push_back(b);
  }
  return set;
}

/// Records every call; asks to stop at the `stopAt`-th wasInterrupted() (0: never).
class RecordingObserver : public StageObserver {
 public:
  explicit RecordingObserver(int stopAt = 0) : stopAt_(stopAt) {}
  void started(double total) override { started_.push_back(total); }
  void progress(double fraction) override { fractions_.push_back(fraction); }
  bool wasInterrupted() override { return ++asked_ == stopAt_; }

  std::vector<double> started_, fractions_;
  int asked_ = 0;

 private:
  int stopAt_;
};

bool sameBits(const std::vector<std::vector<float>>& a, const std::vector<std::vector<float>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t c = 0; c < a.size(); ++c)
    if (a[c].size() != b[c].size() ||
        std::memcmp(a[c].data(), b[c].data(), a[c].size() * sizeof(float)) != 0)
      return false;
  return true;
}

TEST(SynthesisStage, AudioIsTheSynthesizersBitForBit) {
  const BubbleTrackSet tracks = bubblesOver(1.0);
  SynthesisOptions options;
  options.sampleRate = 48000.0;
  options.model.chirp = true;
  RecordingObserver observer;
  const SynthesisStageResult stage = synthesize(tracks, options, observer);

  SynthesisSettings settings;
  settings.sampleRate = 48000.0;
  settings.model.chirp = true;
  const SynthesisResult direct = synthesize(tracks, settings);
  ASSERT_EQ(stage.channels.size(), 2u);
  ASSERT_GT(stage.report.frames, 0);
  EXPECT_TRUE(sameBits(stage.channels, direct.channels));
  EXPECT_EQ(stage.report.frames, direct.report.frames);
  EXPECT_EQ(stage.report.bubblesRendered, direct.report.bubblesRendered);
  EXPECT_EQ(stage.report.oscillatorSamples, direct.report.oscillatorSamples);
  EXPECT_EQ(stage.report.peakPascals, direct.report.peakPascals);
  EXPECT_EQ(stage.durationSeconds(), static_cast<double>(direct.report.frames) / 48000.0);
}

TEST(SynthesisStage, SettingsComeFromTheOptionsElseTheTracks) {
  BubbleTrackSet tracks = bubblesOver(1.0);
  tracks.duration = 2.5;
  SynthesisOptions options;
  SynthesisSettings s = synthesisSettings(tracks, options);
  EXPECT_EQ(s.sampleRate, 44100.0);
  EXPECT_EQ(s.duration, std::optional<double>(2.5));
  options.sampleRate = 96000.0;
  options.duration = 0.5;
  options.model.vapour = !options.model.vapour;
  s = synthesisSettings(tracks, options);
  EXPECT_EQ(s.sampleRate, 96000.0);
  EXPECT_EQ(s.duration, std::optional<double>(0.5));
  EXPECT_EQ(s.model.vapour, options.model.vapour);
  RecordingObserver observer;
  const SynthesisStageResult r = synthesize(tracks, options, observer);
  EXPECT_EQ(r.report.frames, 48000);  // 0.5 s at 96 kHz
}

TEST(SynthesisStage, ObserverSeesStartedThenRisingProgressToTheEnd) {
  BubbleTrackSet tracks = bubblesOver(8.0);
  tracks.duration = 9.0;  // about 3 waves of 8 segments of 16384 samples
  RecordingObserver observer;
  synthesize(tracks, {}, observer);
  EXPECT_EQ(observer.started_, std::vector<double>{9.0});
  ASSERT_GE(observer.fractions_.size(), 2u);
  for (std::size_t i = 1; i < observer.fractions_.size(); ++i)
    EXPECT_GT(observer.fractions_[i], observer.fractions_[i - 1]);
  EXPECT_EQ(observer.fractions_.back(), 1.0);
  EXPECT_EQ(observer.asked_, static_cast<int>(observer.fractions_.size()));
}

TEST(SynthesisStage, ObserverStopsItWithStageInterrupted) {
  BubbleTrackSet tracks = bubblesOver(8.0);
  tracks.duration = 9.0;
  RecordingObserver observer(2);
  try {
    synthesize(tracks, {}, observer);
    FAIL() << "the stage did not stop";
  } catch (const StageInterrupted& e) {
    EXPECT_TRUE(std::string(e.what()).starts_with("synth, ")) << e.what();
    EXPECT_TRUE(std::string(e.what()).ends_with(" % rendered")) << e.what();
  }
  EXPECT_EQ(observer.asked_, 2);
  EXPECT_EQ(observer.fractions_.size(), 1u) << "no progress after the stop";
}

}  // namespace
}  // namespace fluidsound::acoustics
